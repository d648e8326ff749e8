// SPDX-License-Identifier: Apache-2.0
// Input checks and sample sanitising shared by the peers (plain C++).
#pragma once

#include <cstddef>
#include <string_view>

#include "extract/node_samples.h"

namespace strielad::peers {

// \error kInvalidArgument naming `who` if an axis has fewer than 2 values, is not
// strictly monotonic or not finite, or a field does not hold sample_count() values.
void check_node_samples(const NodeSamples& samples, std::string_view who);

// \error kInvalidArgument naming `who` if `field` is not an index into samples.fields.
void check_field_index(const NodeSamples& samples, std::size_t field, std::string_view who);

// Largest magnitude a sample keeps: ±Inf is clamped to ±kClampMagnitude so that linear
// interpolation between samples stays finite in float.
inline constexpr float kClampMagnitude = 1e37f;
// Largest magnitude of a NaN replacement (below FLT_MAX - kClampMagnitude).
inline constexpr double kFarMagnitude = 1e38;

// A value far below `threshold` (threshold - 1e6 (|threshold| + 1), at least
// -kFarMagnitude) and far above it: what NaN samples are replaced by so that they count
// as outside. A clip edge from a valid sample v to such a value is cut at a fraction
// (v - threshold) / (v - replacement) of the edge from v: about 1e-6 or less when
// |v - threshold| is of the order of |threshold| + 1.
double far_below(double threshold);
double far_above(double threshold);

// NaN -> nan_value, ±Inf -> ±kClampMagnitude, others unchanged.
inline float sanitize_sample(float v, float nan_value) {
  if (v != v) return nan_value;
  if (v > kClampMagnitude) return kClampMagnitude;
  if (v < -kClampMagnitude) return -kClampMagnitude;
  return v;
}

}  // namespace strielad::peers
