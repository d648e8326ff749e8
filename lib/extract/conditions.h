// SPDX-License-Identifier: Apache-2.0
// A sub-volume inside one node as a list of half-space conditions on the sample
// lattice: each condition has a value per sample and the region is where every
// condition's piecewise-linear interpolant is >= 0. Limits give `value - min` and
// `max - value`, the domain box gives signed index distances, fill gives a validity
// condition (+1 valid, -1 missing, so the region ends half-way to a missing sample).
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "extract/extract_request.h"
#include "extract/node_samples.h"

namespace strielad {

// kSample: one of ExtractRequest::sample_conditions (a geographic box's side).
enum class ConditionKind : std::uint8_t { kLimitMin, kLimitMax, kBox, kValidity, kSample };

struct Condition {
  ConditionKind kind = ConditionKind::kLimitMin;
  std::uint32_t field = 0;  // limits: the field
  int axis = 0;             // box: the axis (0 x, 1 y, 2 z)
  int side = 0;             // box: 0 lower bound, 1 upper bound
  // Limits: the field's samples and the bound (value - min, max - value; 0 where the
  // sample is missing), computed where needed. Others: one value per sample.
  const float* samples = nullptr;
  double bound = 0;
  std::vector<double> values;

  // The condition's value at sample i (x fastest); inside where >= 0.
  double value(std::size_t i) const {
    if (samples == nullptr) return values[i];
    const double v = samples[i];
    if (!(std::fabs(v) <= static_cast<double>(std::numeric_limits<float>::max()))) return 0.0;
    return kind == ConditionKind::kLimitMin ? v - bound : bound - v;
  }
};

inline constexpr std::size_t kMaxConditions = 60;

// Per sample, one bit per condition: narrow masks when the request can make at most 16
// conditions (every scene of a few limits and a domain box), a quarter of the memory
// the kernel streams through; 64-bit masks otherwise.
inline constexpr std::size_t kNarrowMaskConditions = 16;

struct ConditionSet {
  std::vector<Condition> conditions;  // only conditions not met everywhere
  bool empty = false;                 // a condition excludes every sample
  bool narrow = false;                // masks in inside16, else in inside64
  std::vector<std::uint16_t> inside16;  // per sample: bit c set iff condition c holds
  std::vector<std::uint64_t> inside64;
  std::uint64_t all = 0;              // bits of every condition
  // Node sides (bit 2 * axis + side, as NodeSamples::grid_edge) on which a domain box
  // bound lies exactly, with the box's inside towards the node: the box condition holds
  // everywhere and is dropped, but the region ends there, so the node's face on that
  // side is a domain-box face, not one shared with the neighbouring node (whose part of
  // the box is empty).
  std::uint8_t box_sides = 0;
  // Value buffers of earlier builds, reused by the next build into this set.
  std::vector<std::vector<double>> spare;
};

// Throws kInvalidArgument for a request the samples cannot serve (field index out of
// range, min > max, NaN bounds, too many conditions).
ConditionSet build_conditions(const NodeSamples& samples, const ExtractRequest& request);

// The same into `set`, reusing its buffers (the kernel keeps one set per thread, so a
// node's conditions cost no fresh pages).
void build_conditions(const NodeSamples& samples, const ExtractRequest& request,
                      ConditionSet& set);

// Fractional sample index of axis coordinate `value` on `coords` (ascending or
// descending); below the first sample gives -1, beyond the last gives size().
double fractional_index(const std::vector<double>& coords, double value);

}  // namespace strielad
