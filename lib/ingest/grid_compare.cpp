// SPDX-License-Identifier: Apache-2.0
#include "ingest/grid_compare.h"

#include <fmt/format.h>

namespace strielad::ingest {

std::optional<std::string> axis_difference(const Axis& got, const Axis& want,
                                           std::string_view want_where) {
  if (got.values.size() != want.values.size()) {
    if (got.name == want.name) {
      return fmt::format("axis '{}' has {} values but {} has {}", got.name, got.size(),
                         want_where, want.size());
    }
    return fmt::format("axis '{}' has {} values but axis '{}' in {} has {}", got.name,
                       got.size(), want.name, want_where, want.size());
  }
  if (got.name != want.name) {
    return fmt::format("axis '{}' does not match axis '{}' in {} (the names differ)", got.name,
                       want.name, want_where);
  }
  if (got.units != want.units) {
    return fmt::format("axis '{}' has units '{}' but {} has '{}'", got.name, got.units,
                       want_where, want.units);
  }
  for (std::size_t i = 0; i < got.values.size(); ++i) {
    // Exact: bit-for-bit equal values (both NaN-free, checked when scanned).
    if (got.values[i] != want.values[i]) {
      return fmt::format("axis '{}' value[{}] = {} but {} has {}", got.name, i, got.values[i],
                         want_where, want.values[i]);
    }
  }
  return std::nullopt;
}

std::optional<std::string> grid_difference(const Axis& got_x, const Axis& got_y,
                                           const Axis& got_z, const Axis& want_x,
                                           const Axis& want_y, const Axis& want_z,
                                           std::string_view want_where) {
  if (auto d = axis_difference(got_x, want_x, want_where)) return d;
  if (auto d = axis_difference(got_y, want_y, want_where)) return d;
  return axis_difference(got_z, want_z, want_where);
}

}  // namespace strielad::ingest
