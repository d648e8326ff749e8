// SPDX-License-Identifier: Apache-2.0
// A dimension of a data variable without a coordinate variable cannot be placed.
#include <gtest/gtest.h>

#include "support/expect_error.h"
#include "ingest/input_catalog.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

void write_without_lev_coordinate(const std::filesystem::path& path) {
  NetcdfFixture()
      .coordinate("time", {0}, {NcAttr::text_value("units", "hours since 2000-01-01")}, NC_DOUBLE,
                  true)
      .dimension("lev", 2)
      .coordinate("lat", {0, 1}, {NcAttr::text_value("units", "degrees_north")})
      .coordinate("lon", {0, 1, 2}, {NcAttr::text_value("units", "degrees_east")})
      .variable("T", NC_FLOAT, {"time", "lev", "lat", "lon"}, ramp(12))
      .write(path);
}

TEST(MissingCoordinateVariableTest, DefaultScanNamesFileVariableAndDimension) {
  TempDir dir;
  write_without_lev_coordinate(dir / "nolev.nc");
  expect_error([&] { scan_inputs({dir / "nolev.nc"}, {}); }, ErrorCode::kInvalidInput,
               {(dir / "nolev.nc").string() +
                ": variable 'T' dimension 'lev' has no coordinate variable"});
}

TEST(MissingCoordinateVariableTest, RequestedVariable) {
  TempDir dir;
  write_without_lev_coordinate(dir / "nolev.nc");
  ScanOptions o;
  o.variables = {"T"};
  expect_error([&] { scan_inputs({dir / "nolev.nc"}, o); }, ErrorCode::kInvalidInput,
               {"variable 'T' dimension 'lev' has no coordinate variable"});
}

}  // namespace
}  // namespace strielad::ingest
