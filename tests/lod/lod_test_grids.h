// SPDX-License-Identifier: Apache-2.0
// Synthetic manifests for the level-of-detail tests: only the axes matter.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "format/manifest.h"

namespace strielad::lod::testing {

// n values from `first` to `last` (either order), evenly spaced.
inline std::vector<double> linspace(double first, double last, std::size_t n) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    v[i] = n == 1 ? first : first + (last - first) * static_cast<double>(i) / static_cast<double>(n - 1);
  }
  v.back() = last;
  return v;
}

// Heights from 21 km down to 20 m, stored top to bottom and denser near the ground (as
// ICON's stretched levels).
inline std::vector<double> stretched_heights(std::size_t n) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double s = static_cast<double>(n - 1 - i) / static_cast<double>(n - 1);
    v[i] = 20.0 + (21000.0 - 20.0) * s * s;
  }
  return v;
}

// Longitude 4.5..14.5 ascending, latitude 54.5..47.5 descending (north to south).
inline format::Manifest geographic_manifest(std::size_t nx, std::size_t ny, std::vector<double> z,
                                            AxisKind z_kind = AxisKind::kHeight,
                                            const char* z_units = "m", std::uint32_t brick = 24) {
  format::Manifest m;
  m.x = Axis{"lon", AxisKind::kLongitude, "degrees_east", "longitude", "", "", linspace(4.5, 14.5, nx)};
  m.y = Axis{"lat", AxisKind::kLatitude, "degrees_north", "latitude", "", "", linspace(54.5, 47.5, ny)};
  m.z = Axis{z_kind == AxisKind::kPressure ? "plev" : "height", z_kind, z_units, "", "",
             z_kind == AxisKind::kPressure ? "down" : "up", std::move(z)};
  m.time = TimeAxis{"time", "seconds since 2013-04-26 00:00:00", "standard", {0}};
  m.brick = brick;
  return m;
}

// The paper's grid: 1429 x 1556 x 150 samples, brick 20 (51,393 octree nodes).
inline format::Manifest paper_manifest() {
  return geographic_manifest(1429, 1556, stretched_heights(150), AxisKind::kHeight, "m", 20);
}

// A small grid for exhaustive checks: 97 x 81 x 33 samples, brick 8.
inline format::Manifest small_manifest() {
  return geographic_manifest(97, 81, stretched_heights(33), AxisKind::kHeight, "m", 8);
}

}  // namespace strielad::lod::testing
