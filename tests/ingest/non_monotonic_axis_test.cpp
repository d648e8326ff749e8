// SPDX-License-Identifier: Apache-2.0
// Axes must be strictly monotonic (either direction); anything else names file and axis.
#include <gtest/gtest.h>

#include "support/expect_error.h"
#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
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

// Longitudes wrapped at the antimeridian are made continuous (docs/robustness.md,
// "lon-wrapped-at-180"); the data keeps its order.
TEST(NonMonotonicAxisTest, LongitudesWrappedAt180AreUnwrapped) {
  TempDir dir;
  SimpleGrid g;
  g.lon = {179.0, 179.5, 180.0, -179.5, -179.0};
  NetcdfFixture().grid(g).variable("T", NC_FLOAT, g.dims(), ramp(g.samples())).write(dir / "w.nc");
  const InputCatalog c = scan_inputs({dir / "w.nc"}, {});
  EXPECT_EQ(c.x.values, (std::vector<double>{179.0, 179.5, 180.0, 180.5, 181.0}));
  SlabReader reader(c, {});
  std::vector<float> out(g.lev.size() * g.lat.size() * g.lon.size());
  reader.read(0, 0, 0, g.lev.size(), out);
  EXPECT_EQ(out[3], 3.0f);  // data order unchanged
}

TEST(NonMonotonicAxisTest, DescendingLongitudesWrappedAt0AreUnwrapped) {
  TempDir dir;
  SimpleGrid g;
  g.lon = {2.0, 1.0, 0.0, 359.0, 358.0};
  NetcdfFixture().grid(g).variable("T", NC_FLOAT, g.dims(), ramp(g.samples())).write(dir / "w.nc");
  const InputCatalog c = scan_inputs({dir / "w.nc"}, {});
  EXPECT_EQ(c.x.values, (std::vector<double>{2.0, 1.0, 0.0, -1.0, -2.0}));
}

TEST(NonMonotonicAxisTest, LongitudesThatDoNotUnwrapStayRejected) {
  SimpleGrid g;
  g.lon = {0, 90, 45, 180};  // going back without a wrap
  const auto message = scan_with(g);
  EXPECT_NE(message.find("axis 'lon' is not strictly monotonic"), std::string::npos) << message;
}

TEST(NonMonotonicAxisTest, OnlyLongitudesAreUnwrapped) {
  SimpleGrid g;
  g.lat = {-10, 0, 10};
  g.lev = {100, 300, -50};  // unwrapping by 360 would make it monotonic: not for levels
  const auto message = scan_with(g);
  EXPECT_NE(message.find("axis 'lev' is not strictly monotonic"), std::string::npos) << message;
}

}  // namespace
}  // namespace strielad::ingest
