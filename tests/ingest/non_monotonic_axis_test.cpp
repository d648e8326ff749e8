// SPDX-License-Identifier: Apache-2.0
// Axes must be strictly monotonic (either direction); anything else names file and axis.
#include <gtest/gtest.h>

#include "support/expect_error.h"
#include "ingest/input_catalog.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

std::string scan_with(SimpleGrid g) {
  TempDir dir;
  const auto path = dir / "axis.nc";
  NetcdfFixture().grid(g).variable("T", NC_FLOAT, g.dims(), ramp(g.samples())).write(path);
  return expect_error([&] { scan_inputs({path}, {}); }, ErrorCode::kInvalidInput,
                      {path.string()});
}

TEST(NonMonotonicAxisTest, LatitudeGoingBackIsRejected) {
  SimpleGrid g;
  g.lat = {0, 10, 5};
  const auto message = scan_with(g);
  EXPECT_NE(message.find("axis 'lat' is not strictly monotonic"), std::string::npos) << message;
}

TEST(NonMonotonicAxisTest, RepeatedLevelIsRejected) {
  SimpleGrid g;
  g.lev = {1000, 850, 850};
  const auto message = scan_with(g);
  EXPECT_NE(message.find("axis 'lev' is not strictly monotonic"), std::string::npos) << message;
}

TEST(NonMonotonicAxisTest, TimeAxisWithinAFileMustBeMonotonic) {
  SimpleGrid g;
  g.time = {0, 12, 6};
  const auto message = scan_with(g);
  EXPECT_NE(message.find("axis 'time' is not strictly monotonic"), std::string::npos) << message;
}

TEST(NonMonotonicAxisTest, DescendingAxesAreFine) {
  TempDir dir;
  SimpleGrid g;
  g.lat = {10, 0, -10};
  g.lev = {100, 500, 1000};
  g.lon = {270, 180, 90, 0};
  NetcdfFixture().grid(g).variable("T", NC_FLOAT, g.dims(), ramp(g.samples())).write(dir / "d.nc");
  const InputCatalog c = scan_inputs({dir / "d.nc"}, {});
  EXPECT_TRUE(c.y.descending());
  EXPECT_FALSE(c.z.descending());
  EXPECT_TRUE(c.x.descending());
  EXPECT_EQ(c.y.values, g.lat);
}

}  // namespace
}  // namespace strielad::ingest
