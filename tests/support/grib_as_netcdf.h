// SPDX-License-Identifier: Apache-2.0
// NetCDF and GRIB files cut from one real GRIB file, for conversions that mix the two
// formats: one GRIB variable written as CF-NetCDF on the very axes, grid mapping and
// validity times the GRIB catalog gives it (values as ecCodes decodes them, in float), or
// as a smaller GRIB file holding only its messages. A spec can make the netCDF copy
// differ in one way (fewer columns, another time, another projection) for refusals.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

namespace strielad::testing {

struct GribAsNetcdf {
  std::string short_name = "t";  // the GRIB variable copied
  std::string name = "t";        // its name in the netCDF file
  std::size_t drop_columns = 0;  // columns left out at the end of each row
  double hours_later = 0;        // added to the validity time
  double central_meridian_shift = 0;  // added to longitude_of_central_meridian
  bool with_time = true;              // false: no time dimension at all
};

// Written as netCDF-4 with time "hours since 1970-01-01 00:00:00" (calendar "gregorian"),
// the levels as "plev" (hPa), x and y in metres, the mapping as variable "lcc".
// Throws what the GRIB scan or netCDF throws.
void write_grib_variable_as_netcdf(const std::filesystem::path& grib, const GribAsNetcdf& spec,
                                   const std::filesystem::path& out);

// The messages of GRIB variable `short_name` (every level and time of the first
// variable of that shortName), copied byte for byte into `out`.
void copy_grib_variable(const std::filesystem::path& grib, const std::string& short_name,
                        const std::filesystem::path& out);

}  // namespace strielad::testing
