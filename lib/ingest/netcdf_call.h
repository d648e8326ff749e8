// SPDX-License-Identifier: Apache-2.0
// netCDF-C (and the serial HDF5 under it) is not thread-safe: every call into it goes
// through netcdf_mutex(). nc_check turns a netCDF status into a strielad::Error.
#pragma once

#include <mutex>
#include <string_view>

namespace strielad::ingest {

std::mutex& netcdf_mutex();

// Throws Error(kIo, or kInvalidInput for format errors) "<context>: <nc_strerror>" when
// status != NC_NOERR.
void nc_check(int status, std::string_view context);

}  // namespace strielad::ingest
