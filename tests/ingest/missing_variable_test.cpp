// SPDX-License-Identifier: Apache-2.0
// A requested variable that no input has is kNotFound, naming it and what is available.
#include <gtest/gtest.h>

#include "support/expect_error.h"
#include "ingest/input_catalog.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

TEST(MissingVariableTest, RequestedVariableAbsentFromEveryFile) {
  TempDir dir;
  SimpleGrid g;
  NetcdfFixture().grid(g).variable("T", NC_FLOAT, g.dims(), ramp(g.samples())).write(dir / "a.nc");
  NetcdfFixture().grid(g).variable("U", NC_FLOAT, g.dims(), ramp(g.samples())).write(dir / "b.nc");
  ScanOptions o;
  o.variables = {"T", "Q"};
  expect_error([&] { scan_inputs({dir / "a.nc", dir / "b.nc"}, o); }, ErrorCode::kNotFound,
               {"variable 'Q' not found", "available variables: T, U"});
}

TEST(MissingVariableTest, MissingInSingleFileNamesTheFile) {
  TempDir dir;
  SimpleGrid g;
  NetcdfFixture().grid(g).variable("T", NC_FLOAT, g.dims(), ramp(g.samples())).write(dir / "a.nc");
  ScanOptions o;
  o.variables = {"grp1/T"};
  expect_error([&] { scan_inputs({dir / "a.nc"}, o); }, ErrorCode::kNotFound,
               {"'grp1/T'", (dir / "a.nc").string(), "available variables: T"});
}

TEST(MissingVariableTest, NoThreeDimensionalVariableAtAll) {
  TempDir dir;
  NetcdfFixture()
      .coordinate("lat", {0, 1}, {NcAttr::text_value("units", "degrees_north")})
      .coordinate("lon", {0, 1}, {NcAttr::text_value("units", "degrees_east")})
      .variable("orog", NC_FLOAT, {"lat", "lon"}, ramp(4))
      .write(dir / "flat.nc");
  expect_error([&] { scan_inputs({dir / "flat.nc"}, {}); }, ErrorCode::kNotFound,
               {"no 3D variable", "flat.nc", "orog"});
}

TEST(MissingVariableTest, VariableRequestedTwiceIsAnInvalidArgument) {
  TempDir dir;
  SimpleGrid g;
  NetcdfFixture().grid(g).variable("T", NC_FLOAT, g.dims(), ramp(g.samples())).write(dir / "a.nc");
  ScanOptions o;
  o.variables = {"T", "/T"};
  expect_error([&] { scan_inputs({dir / "a.nc"}, o); }, ErrorCode::kInvalidArgument,
               {"'T'", "twice"});
}

}  // namespace
}  // namespace strielad::ingest
