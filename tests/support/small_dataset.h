// SPDX-License-Identifier: Apache-2.0
// A small CF-NetCDF dataset with the three kinds of data a store must keep exactly:
// "cloud" (float, mostly exactly 0, blobs, a block of _FillValue holes), "temp" (double,
// dense) and "packed" (short with scale_factor/add_offset and _FillValue). Axes: lon
// ascending non-uniform, lat descending, lev in hPa descending. One file per step.
#pragma once

#include <filesystem>
#include <vector>

#include "convert/converter.h"

namespace strielad::testing {

struct SmallDataset {
  std::size_t nx = 23, ny = 17, nz = 11, steps = 2;
  std::vector<std::filesystem::path> files;
};

SmallDataset write_small_dataset(const std::filesystem::path& dir, std::size_t nx = 23,
                                 std::size_t ny = 17, std::size_t nz = 11, std::size_t steps = 2);

// Value of "cloud" at (x, y, z, step) as written (NaN where the file holds _FillValue).
double small_cloud_value(std::size_t x, std::size_t y, std::size_t z, std::size_t step);

build::ConvertOptions small_convert_options(const SmallDataset& data,
                                            const std::filesystem::path& store,
                                            std::uint32_t brick = 4);

}  // namespace strielad::testing
