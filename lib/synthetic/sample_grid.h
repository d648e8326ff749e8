// SPDX-License-Identifier: Apache-2.0
// The coordinates of the sample dataset: a uniform lon/lat grid over Germany like the
// regridded ICON-LEM output (4.5-14.5 E, 47.5-54.5 N) and a stretched height axis stored
// top to bottom (about 21 km down to 20 m, fine near the ground). Every grid size covers
// the same domain, so a small grid is a coarse view of the same atmosphere.
#pragma once

#include <cstddef>
#include <vector>

#include "grid/axis.h"

namespace strielad::synthetic {

inline constexpr double kLonMin = 4.5, kLonMax = 14.5;    // degrees_east
inline constexpr double kLatMin = 47.5, kLatMax = 54.5;   // degrees_north
inline constexpr double kModelTop = 21000.0;              // m, the highest level
inline constexpr double kLowestLevel = 20.0;              // m, the lowest level
inline constexpr double kHeightStretch = 3.2;             // larger: finer near the ground

// n values from lo to hi inclusive (the midpoint when n == 1).
std::vector<double> uniform_axis(std::size_t n, double lo, double hi);

// n heights in metres, strictly descending from kModelTop to kLowestLevel (index 0 is
// the top, like ICON); spacing grows exponentially with height.
std::vector<double> stretched_heights(std::size_t n);

struct SampleGrid {
  Dims3 dims;
  std::vector<double> lon, lat, height;  // sizes x, y, z; height descending
  // Horizontal positions in km on a local tangent plane centred on the domain; the
  // physical fields are functions of (x_km, y_km, height, time) only.
  std::vector<double> x_km, y_km;

  explicit SampleGrid(Dims3 dims);
  std::size_t level_size() const { return dims.x * dims.y; }
};

}  // namespace strielad::synthetic
