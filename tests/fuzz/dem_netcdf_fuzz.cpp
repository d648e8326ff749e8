// SPDX-License-Identifier: Apache-2.0
// Fuzzes the CF-NetCDF DEM reader (scenery/dem_source.h, open_netcdf_dem) on the input
// written to a file: opening, a strided read of the whole grid and georeferencing must
// reject with strielad::Error, never crash. Seeds are classic-format (CDF-2) DEMs on
// lon/lat axes (descending latitude, fill, km) and on a rotated-pole grid mapping;
// netCDF-C parses the container.
#include "core/error.h"
#include "fuzz/dem_checks.h"
#include "fuzz/fuzz_files.h"
#include "fuzz/fuzz_target.h"
#include "support/netcdf_fixture.h"

using namespace strielad;
using strielad::testing::NcAttr;
using strielad::testing::NetcdfFixture;

std::vector<std::vector<std::uint8_t>> strielad_fuzz_seeds() {
  const auto lonlat = [](const std::filesystem::path& path) {
    NetcdfFixture(NC_64BIT_OFFSET)
        .coordinate("lat", {54, 53, 52, 51, 50}, {NcAttr::text_value("units", "degrees_north")})
        .coordinate("lon", {6, 7, 8, 9}, {NcAttr::text_value("units", "degrees_east")})
        .variable("elevation", NC_FLOAT, {"lat", "lon"},
                  {0, 1, 2, 3, 100, 101, 102, 103, 200, -32768, 202, 203, 300, 301, 302, 303,
                   400, 401, 402, 403},
                  {NcAttr::text_value("units", "km"),
                   NcAttr::number("_FillValue", NC_FLOAT, {-32768})})
        .write(path);
  };
  const auto rotated = [](const std::filesystem::path& path) {
    NetcdfFixture(NC_64BIT_OFFSET)
        .dimension("time", 1, true)
        .coordinate("rlat", {-1, -0.5, 0}, {NcAttr::text_value("standard_name", "grid_latitude"),
                                             NcAttr::text_value("units", "degrees")})
        .coordinate("rlon", {-2, -1.5, -1, -0.5}, {NcAttr::text_value("standard_name", "grid_longitude"),
                                                   NcAttr::text_value("units", "degrees")})
        .variable("rotated_pole", NC_INT, {}, {0},
                  {NcAttr::text_value("grid_mapping_name", "rotated_latitude_longitude"),
                   NcAttr::number("grid_north_pole_latitude", NC_FLOAT, {39.25}),
                   NcAttr::number("grid_north_pole_longitude", NC_FLOAT, {-162})})
        .variable("HSURF", NC_SHORT, {"time", "rlat", "rlon"}, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, -1},
                  {NcAttr::text_value("standard_name", "surface_altitude"),
                   NcAttr::text_value("units", "m"), NcAttr::text_value("grid_mapping", "rotated_pole"),
                   NcAttr::number("scale_factor", NC_FLOAT, {10}),
                   NcAttr::number("add_offset", NC_FLOAT, {-5}),
                   NcAttr::number("missing_value", NC_SHORT, {-1})})
        .write(path);
  };
  return {fuzz::bytes_written_by(".nc", lonlat), fuzz::bytes_written_by(".nc", rotated)};
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    fuzz::exercise_dem(*geo::open_netcdf_dem(fuzz::input_file(data, size, ".nc"), ""));
  } catch (const Error&) {
  }
  return 0;
}
