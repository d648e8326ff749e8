// SPDX-License-Identifier: Apache-2.0
// What the DEM fuzz targets do with a DEM that opened: read the whole grid through a
// strided window of at most 32 x 32 samples, one corner sample, and georeference the
// corners and the centre, as the terrain does (scenery/dem_source.h).
#pragma once

#include <algorithm>
#include <array>
#include <cstdlib>

#include "scenery/dem_source.h"

namespace strielad::fuzz {

inline void exercise_dem(const geo::DemSource& dem) {
  const std::size_t w = dem.width(), h = dem.height();
  if (w == 0 || h == 0) std::abort();  // the readers promise a grid
  const std::size_t stride = std::max<std::size_t>(1, std::max(w, h) / 32 + 1);
  const geo::DemWindow all{0, 0, (w - 1) / stride + 1, (h - 1) / stride + 1, stride};
  if (dem.read(all).size() != all.cols * all.rows) std::abort();
  if (dem.read({w - 1, h - 1, 1, 1, 1}).size() != 1) std::abort();
  const std::array<double, 5> cols{0, double(w - 1), 0, double(w - 1), 0.5 * double(w - 1)};
  const std::array<double, 5> rows{0, 0, double(h - 1), double(h - 1), 0.5 * double(h - 1)};
  std::array<geo::LonLat, 5> out{};
  dem.georeference(cols, rows, out);
  (void)dem.describe();
  (void)dem.georeferencing();
}

}  // namespace strielad::fuzz
