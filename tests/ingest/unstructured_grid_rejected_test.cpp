// SPDX-License-Identifier: Apache-2.0
// ICON's native triangular grid (cells with clon/clat), and curvilinear grids whose 2-D
// lat/lon the variable's `coordinates` attribute does not name, are refused with a message
// that says what the grid is and how to remap it (curvilinear_grid_test.cpp: the ones it
// names are converted).
#include <gtest/gtest.h>

#include "support/expect_error.h"
#include "ingest/input_catalog.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

TEST(UnstructuredGridRejectedTest, IconTriangularGridByDefault) {
  const auto file = ncarg_file("nug/triangular_grid_ICON.nc");
  expect_error([&] { scan_inputs({file}, {}); }, ErrorCode::kUnsupported,
               {file.string(), "unstructured grid", "dimension 'ncells', coordinates clon clat",
                "only logically rectangular grids are supported", "cdo remapcon"});
}

TEST(UnstructuredGridRejectedTest, IconVariableRequestedByName) {
  const auto file = ncarg_file("nug/triangular_grid_ICON.nc");
  ScanOptions o;
  o.variables = {"S"};
  expect_error([&] { scan_inputs({file}, o); }, ErrorCode::kUnsupported,
               {"triangular_grid_ICON.nc: variable 'S' is on an unstructured grid (dimension "
                "'ncells', coordinates clon clat); only logically rectangular grids are supported "
                "— remap it first (e.g. cdo remapcon)"});
}

TEST(UnstructuredGridRejectedTest, CurvilinearGridWith2DLatLonNotNamedByTheVariable) {
  TempDir dir;
  const std::vector<double> lat2d{10, 10, 10, 20, 21, 22}, lon2d{0, 5, 10, 1, 6, 11};
  NetcdfFixture(NC_NETCDF4)
      .dimension("y", 2)
      .dimension("x", 3)
      .coordinate("lev", {1000, 500}, {NcAttr::text_value("units", "hPa")})
      .variable("lat", NC_DOUBLE, {"y", "x"}, lat2d,
                {NcAttr::text_value("standard_name", "latitude"),
                 NcAttr::text_value("units", "degrees_north")})
      .variable("lon", NC_DOUBLE, {"y", "x"}, lon2d,
                {NcAttr::text_value("standard_name", "longitude"),
                 NcAttr::text_value("units", "degrees_east")})
      .variable("T", NC_FLOAT, {"lev", "y", "x"}, ramp(12))
      .write(dir / "curvilinear.nc");
  ScanOptions o;
  o.variables = {"T"};
  expect_error([&] { scan_inputs({dir / "curvilinear.nc"}, o); }, ErrorCode::kUnsupported,
               {"curvilinear.nc: variable 'T' is on a curvilinear grid", "'y', 'x'", "lat lon",
                "coordinates attribute names a longitude and a latitude", "cdo remapbil"});
}

}  // namespace
}  // namespace strielad::ingest
