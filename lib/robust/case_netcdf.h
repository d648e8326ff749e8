// SPDX-License-Identifier: Apache-2.0
// Writes a robustness case's input as one CF-NetCDF-4 file: dimensions time, height,
// lat, lon with their coordinate variables and CF attributes, and the variable "f"
// (float, double, or short packed with float scale_factor/add_offset). A case without
// values declares "f" chunked and never writes it: the file stays a few KB whatever the
// declared size, and reads of it return the fill value.
#pragma once

#include <filesystem>

#include "robust/extreme_case.h"

namespace strielad::robust {

// \error kIo naming the file when netCDF refuses; kInvalidArgument when the values do
// not match the grid.
void write_case_netcdf(const ExtremeCase& c, const std::filesystem::path& path);

}  // namespace strielad::robust
