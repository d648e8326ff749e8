// SPDX-License-Identifier: Apache-2.0
// Every file must have exactly the same grid: sizes, names, units and values.
#include <gtest/gtest.h>

#include "support/expect_error.h"
#include "ingest/input_catalog.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

std::string scan_pair(SimpleGrid second) {
  TempDir dir;
  SimpleGrid first;
  second.time = {6};
  NetcdfFixture().grid(first).variable("T", NC_FLOAT, first.dims(), ramp(first.samples()))
      .write(dir / "f1.nc");
  NetcdfFixture().grid(second).variable("T", NC_FLOAT, second.dims(), ramp(second.samples()))
      .write(dir / "f2.nc");
  return expect_error([&] { scan_inputs({dir / "f1.nc", dir / "f2.nc"}, {}); },
                      ErrorCode::kInvalidInput, {"(variable 'T')"});
}

TEST(GridMismatchAcrossFilesTest, DifferentLatitudeCount) {
  SimpleGrid g;
  g.lat = {-10, 0, 10, 20};
  const auto message = scan_pair(g);
  EXPECT_NE(message.find("f2.nc: axis 'lat' has 4 values but "), std::string::npos) << message;
  EXPECT_NE(message.find("f1.nc has 3"), std::string::npos) << message;
}

TEST(GridMismatchAcrossFilesTest, DifferentLevelValue) {
  SimpleGrid g;
  g.lev = {1000, 700};
  const auto message = scan_pair(g);
  EXPECT_NE(message.find("f2.nc: axis 'lev' value[1] = 700 but "), std::string::npos) << message;
  EXPECT_NE(message.find("f1.nc has 850"), std::string::npos) << message;
}

TEST(GridMismatchAcrossFilesTest, DifferentLevelUnits) {
  SimpleGrid g;
  g.lev_units = "mbar";
  const auto message = scan_pair(g);
  EXPECT_NE(message.find("axis 'lev' has units 'mbar' but"), std::string::npos) << message;
  EXPECT_NE(message.find("has 'hPa'"), std::string::npos) << message;
}

TEST(GridMismatchAcrossFilesTest, DifferentAxisName) {
  TempDir dir;
  SimpleGrid g;
  NetcdfFixture().grid(g).variable("T", NC_FLOAT, g.dims(), ramp(g.samples())).write(dir / "f1.nc");
  NetcdfFixture()
      .coordinate("time", {6}, {NcAttr::text_value("units", g.time_units),
                                NcAttr::text_value("calendar", "standard")}, NC_DOUBLE, true)
      .coordinate("plev", g.lev, {NcAttr::text_value("units", "hPa")})
      .coordinate("lat", g.lat, {NcAttr::text_value("units", "degrees_north")})
      .coordinate("lon", g.lon, {NcAttr::text_value("units", "degrees_east")})
      .variable("T", NC_FLOAT, {"time", "plev", "lat", "lon"}, ramp(g.samples()))
      .write(dir / "f2.nc");
  expect_error([&] { scan_inputs({dir / "f1.nc", dir / "f2.nc"}, {}); }, ErrorCode::kInvalidInput,
               {"f2.nc: axis 'plev' does not match axis 'lev'", "f1.nc"});
}

}  // namespace
}  // namespace strielad::ingest
