// SPDX-License-Identifier: Apache-2.0
// The viewer's sun (lib/view/sun_direction.h): the true sun over the domain centre at
// a step's time (plus seconds within the step), and no sun where the store has no real
// date or no longitude/latitude.
#include <gtest/gtest.h>

#include <cmath>

#include "geo/cf_time.h"
#include "lod/lod_test_grids.h"
#include "view/sun_direction.h"

namespace strielad::view {
namespace {

format::Manifest manifest_at(const char* units, const char* calendar = "standard") {
  auto m = lod::testing::geographic_manifest(11, 8, {12000.0, 3000.0, 0.0});
  m.time = TimeAxis{"time", units, calendar, {0, 21600, 43200}};
  return m;
}

TEST(SunDirectionTest, TheTrueSunOverTheDomainCentre) {
  const auto m = manifest_at("seconds since 2013-04-26 00:00:00");
  const lod::WorldFrame frame(m);
  const auto midnight = sun_at_step(frame, m, 0);
  const auto noon = sun_at_step(frame, m, 2);
  ASSERT_TRUE(midnight && noon);
  EXPECT_LT(midnight->position.elevation_deg, -20);  // 51 N in late April
  EXPECT_GT(noon->position.elevation_deg, 50);
  EXPECT_LT(noon->direction[1], 0);  // from the south
  const auto expected = geo::solar_position(geo::julian_day(2013, 4, 26, 43200), frame.origin(1),
                                            frame.origin(0));
  for (int a = 0; a < 3; ++a) EXPECT_DOUBLE_EQ(noon->direction[a], expected.east_north_up[a]);
  // Seconds within a step: step 1 (06:00) plus 6 h is noon.
  const auto later = sun_at_step(frame, m, 1, 21600);
  ASSERT_TRUE(later);
  EXPECT_NEAR(later->position.elevation_deg, noon->position.elevation_deg, 1e-9);
  EXPECT_FALSE(sun_at_step(frame, m, 3));  // no such step
}

TEST(SunDirectionTest, NoSunWithoutADateOrAPlace) {
  const auto model = manifest_at("seconds since 2013-04-26 00:00:00", "360_day");
  EXPECT_FALSE(sun_at_step(lod::WorldFrame(model), model, 0));
  const auto steps = manifest_at("steps");
  EXPECT_FALSE(sun_at_step(lod::WorldFrame(steps), steps, 0));
  // A projected grid (x/y in metres; read with kinds longitude/latitude, as ingest does).
  auto metric = manifest_at("seconds since 2013-04-26 00:00:00");
  metric.x = Axis{"x", AxisKind::kLongitude, "m", "", "", "", lod::testing::linspace(0, 1e5, 11)};
  metric.y = Axis{"y", AxisKind::kLatitude, "m", "", "", "", lod::testing::linspace(0, 1e5, 8)};
  EXPECT_FALSE(sun_at_step(lod::WorldFrame(metric), metric, 0));
}

}  // namespace
}  // namespace strielad::view
