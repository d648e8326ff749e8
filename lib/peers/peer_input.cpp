// SPDX-License-Identifier: Apache-2.0
#include "peers/peer_input.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace strielad::peers {

void check_node_samples(const NodeSamples& samples, std::string_view who) {
  static constexpr char kAxisNames[] = "xyz";
  for (int a = 0; a < 3; ++a) {
    const auto& c = samples.coords[a];
    if (c.size() < 2) {
      throw make_error(ErrorCode::kInvalidArgument, "{}: axis {} has {} samples, need at least 2",
                       who, kAxisNames[a], c.size());
    }
    const bool ascending = c[1] > c[0];
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (!std::isfinite(c[i])) {
        throw make_error(ErrorCode::kInvalidArgument, "{}: axis {} value {} is {}", who,
                         kAxisNames[a], i, c[i]);
      }
      if (i > 0 && (ascending ? !(c[i] > c[i - 1]) : !(c[i] < c[i - 1]))) {
        throw make_error(ErrorCode::kInvalidArgument,
                         "{}: axis {} is not strictly monotonic at value {} ({} after {})", who,
                         kAxisNames[a], i, c[i], c[i - 1]);
      }
    }
  }
  for (std::size_t f = 0; f < samples.fields.size(); ++f) {
    if (samples.fields[f].size() != samples.sample_count()) {
      throw make_error(ErrorCode::kInvalidArgument, "{}: field {} has {} values, the lattice {}",
                       who, f, samples.fields[f].size(), samples.sample_count());
    }
  }
}

void check_field_index(const NodeSamples& samples, std::size_t field, std::string_view who) {
  if (field >= samples.fields.size()) {
    throw make_error(ErrorCode::kInvalidArgument, "{}: field {} does not exist (the node has {})",
                     who, field, samples.fields.size());
  }
}

double far_below(double threshold) {
  return std::max(threshold - 1e6 * (std::abs(threshold) + 1.0), -kFarMagnitude);
}

double far_above(double threshold) {
  return std::min(threshold + 1e6 * (std::abs(threshold) + 1.0), kFarMagnitude);
}

}  // namespace strielad::peers
