// SPDX-License-Identifier: Apache-2.0
// A small store of the sample generator's wind (ua, va, wa) and clouds (clw): the
// generator's sheared, rotating wind on a lon/lat/stretched-height grid, two or more
// steps 300 s apart, converted with small bricks so that it has several levels.
#pragma once

#include <filesystem>

#include "grid/axis.h"

namespace strielad::testing {

// Writes the NetCDF files under `dir / "nc"` and converts them into `dir / "wind"`.
std::filesystem::path write_wind_store(const std::filesystem::path& dir,
                                       Dims3 dims = Dims3{48, 40, 24}, std::size_t steps = 2,
                                       unsigned brick = 8);

}  // namespace strielad::testing
