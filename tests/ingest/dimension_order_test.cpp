// SPDX-License-Identifier: Apache-2.0
// Only (time, vertical, lat, lon) order is read; other orders are refused with a hint.
#include <gtest/gtest.h>

#include "support/expect_error.h"
#include "ingest/input_catalog.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

TEST(DimensionOrderTest, LevelLastIsUnsupported) {
  TempDir dir;
  SimpleGrid g;
  g.with_time = false;
  NetcdfFixture().grid(g).variable("T", NC_FLOAT, {"lat", "lon", "lev"}, ramp(g.samples()))
      .write(dir / "order.nc");
  expect_error([&] { scan_inputs({dir / "order.nc"}, {}); }, ErrorCode::kUnsupported,
               {"order.nc: variable 'T' has dimensions (lat, lon, lev)",
                "(latitude, longitude, vertical)", "reorder", "ncpdq -a lev,lat,lon"});
}

TEST(DimensionOrderTest, TimeNotFirstIsUnsupported) {
  TempDir dir;
  SimpleGrid g;
  NetcdfFixture().grid(g).variable("T", NC_FLOAT, {"lev", "time", "lat", "lon"},
                                   ramp(g.samples()))
      .write(dir / "order.nc");
  ScanOptions o;
  o.variables = {"T"};
  expect_error([&] { scan_inputs({dir / "order.nc"}, o); }, ErrorCode::kUnsupported,
               {"(lev, time, lat, lon)", "ncpdq -a time,lev,lat,lon"});
}

TEST(DimensionOrderTest, LonBeforeLatIsUnsupported) {
  TempDir dir;
  SimpleGrid g;
  NetcdfFixture().grid(g).variable("T", NC_FLOAT, {"time", "lev", "lon", "lat"},
                                   ramp(g.samples()))
      .write(dir / "order.nc");
  expect_error([&] { scan_inputs({dir / "order.nc"}, {}); }, ErrorCode::kUnsupported,
               {"(time, lev, lon, lat)", "ncpdq"});
}

TEST(DimensionOrderTest, UnknownCoordinatesFallBackToCoardsPosition) {
  TempDir dir;
  // No attributes at all and names that say nothing: position decides (t, z, y, x).
  NetcdfFixture()
      .coordinate("a", {0, 1})
      .coordinate("b", {5, 6, 7})
      .coordinate("c", {10, 20})
      .coordinate("d", {1, 2, 3, 4})
      .variable("Q", NC_FLOAT, {"a", "b", "c", "d"}, ramp(48))
      .write(dir / "coards.nc");
  const InputCatalog c = scan_inputs({dir / "coards.nc"}, {});
  EXPECT_EQ(c.x.name, "d");
  EXPECT_EQ(c.y.name, "c");
  EXPECT_EQ(c.z.name, "b");
  EXPECT_EQ(c.z.kind, AxisKind::kOther);
  EXPECT_EQ(c.time.name, "a");
  EXPECT_EQ(c.time.values, (std::vector<double>{0, 1}));
}

}  // namespace
}  // namespace strielad::ingest
