// SPDX-License-Identifier: Apache-2.0
// The viewer's sun (lib/view/sun_direction.h): the true sun over the domain centre at
// a step's time (plus seconds within the step); over a domain wider than 30 degrees of
// longitude the sun of its sunniest point, so a global domain whose centre is at night
// is lit as its day side; model calendars keep their season and time of day; and no
// sun where the store has no date or no longitude/latitude.
#include <gtest/gtest.h>

#include <algorithm>
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
  const auto expected = geo::solar_position(geo::julian_day(2013, 4, 26, 43200), frame.lat0(),
                                            frame.lon0());
  for (int a = 0; a < 3; ++a) EXPECT_DOUBLE_EQ(noon->direction[a], expected.east_north_up[a]);
  // Seconds within a step: step 1 (06:00) plus 6 h is noon.
  const auto later = sun_at_step(frame, m, 1, 21600);
  ASSERT_TRUE(later);
  EXPECT_NEAR(later->position.elevation_deg, noon->position.elevation_deg, 1e-9);
  EXPECT_FALSE(sun_at_step(frame, m, 3));  // no such step
}

TEST(SunDirectionTest, NoSunWithoutADateOrAPlace) {
  const auto none = manifest_at("seconds since 2013-04-26 00:00:00", "none");
  EXPECT_FALSE(sun_at_step(lod::WorldFrame(none), none, 0));
  const auto steps = manifest_at("steps");
  EXPECT_FALSE(sun_at_step(lod::WorldFrame(steps), steps, 0));
  // A projected grid (x/y in metres; read with kinds longitude/latitude, as ingest does).
  auto metric = manifest_at("seconds since 2013-04-26 00:00:00");
  metric.x = Axis{"x", AxisKind::kLongitude, "m", "", "", "", lod::testing::linspace(0, 1e5, 11)};
  metric.y = Axis{"y", AxisKind::kLatitude, "m", "", "", "", lod::testing::linspace(0, 1e5, 8)};
  EXPECT_FALSE(sun_at_step(lod::WorldFrame(metric), metric, 0));
}

TEST(SunDirectionTest, ModelCalendarsKeepTheirSeasonAndTimeOfDay) {
  // 360_day 2013-04-26 is day 115 of 360: day floor(115 * 365 / 360) = 116 of 2013, 27 April.
  const auto model = manifest_at("seconds since 2013-04-26 00:00:00", "360_day");
  const lod::WorldFrame frame(model);
  const auto noon = sun_at_step(frame, model, 2);
  ASSERT_TRUE(noon);
  const auto expected = geo::solar_position(geo::julian_day(2013, 4, 27, 43200), frame.lat0(),
                                            frame.lon0());
  for (int a = 0; a < 3; ++a) EXPECT_DOUBLE_EQ(noon->direction[a], expected.east_north_up[a]);
  // noleap 2000-03-01 06:00 (day 59 of 365) is 2000-02-29 06:00 of the leap year (day 59 of 366).
  const auto noleap = manifest_at("hours since 2000-03-01 00:00:00", "noleap");
  const auto morning = sun_at_step(lod::WorldFrame(noleap), noleap, 0, 6 * 3600);
  ASSERT_TRUE(morning);
  const auto at = geo::solar_position(geo::julian_day(2000, 2, 29, 6 * 3600), frame.lat0(), frame.lon0());
  for (int a = 0; a < 3; ++a) EXPECT_DOUBLE_EQ(morning->direction[a], at.east_north_up[a]);
  // The real calendars are unchanged: 2013-04-26 noon is 2013-04-26 noon.
  const auto real = manifest_at("seconds since 2013-04-26 00:00:00", "proleptic_gregorian");
  const auto real_noon = sun_at_step(lod::WorldFrame(real), real, 2);
  ASSERT_TRUE(real_noon);
  const auto same = geo::solar_position(geo::julian_day(2013, 4, 26, 43200), frame.lat0(), frame.lon0());
  for (int a = 0; a < 3; ++a) EXPECT_DOUBLE_EQ(real_noon->direction[a], same.east_north_up[a]);
}

// A global grid like a 2.5-degree forecast at 12 UTC on 21 June: the domain centre
// (178.75 E, 0 N) is at midnight.
format::Manifest global_manifest(double lon_first = 0, double lon_last = 357.5) {
  format::Manifest m;
  m.x = Axis{"lon", AxisKind::kLongitude, "degrees_east", "longitude", "", "",
             lod::testing::linspace(lon_first, lon_last, 144)};
  m.y = Axis{"lat", AxisKind::kLatitude, "degrees_north", "latitude", "", "",
             lod::testing::linspace(90, -90, 73)};
  m.z = Axis{"plev", AxisKind::kPressure, "Pa", "", "", "down", lod::testing::linspace(100000, 1000, 26)};
  m.time = TimeAxis{"time", "hours since 2024-06-21 00:00:00", "standard", {12}};
  m.brick = 16;
  return m;
}

TEST(SunDirectionTest, GlobalDomainIsLitAsItsDaySide) {
  const auto m = global_manifest();
  const lod::WorldFrame frame(m);
  EXPECT_NEAR(domain_longitude_span_deg(frame), 357.5, 1e-9);
  const auto sun = sun_at_step(frame, m, 0);
  ASSERT_TRUE(sun);
  // The centre's own sun is far below the horizon...
  const double jd = geo::julian_day(2024, 6, 21, 43200);
  EXPECT_LT(geo::solar_position(jd, frame.lat0(), frame.lon0()).elevation_deg, -60);
  // ...the viewer's is overhead: seen from the sub-solar point (23.4 N, near 0 E at noon
  // UTC), which the domain holds.
  EXPECT_EQ(sun->viewpoint, SunViewpoint::kSunniestPoint);
  EXPECT_GT(sun->position.elevation_deg, 89.9);
  EXPECT_GT(sun->direction[2], 0.9999);
  EXPECT_NEAR(sun->latitude_deg, 23.44, 0.01);
  const double lon = std::fmod(sun->longitude_deg + 360.0, 360.0);
  EXPECT_LT(std::min(lon, 360.0 - lon), 2.0);  // noon UTC, give or take the equation of time
  EXPECT_NE(describe_sun(*sun).find("sunniest point (23.44 N"), std::string::npos) << describe_sun(*sun);
}

// The sunniest point against a search over a lattice of the domain, for domains that
// hold the sub-solar point and domains that do not (west, east, north and south of it,
// across the antimeridian), at several times.
TEST(SunDirectionTest, SunniestPointIsWhereTheSunIsHighest) {
  struct Domain {
    double lon_lo, lon_hi, lat_lo, lat_hi;
  };
  const Domain domains[] = {{0, 357.5, -90, 90},   {-30, 40, 30, 70},  {100, 140, -50, -10},
                            {160, 220, 40, 60},    {-80, -40, -30, 0}, {20, 60, 60, 90},
                            {-100, -60, 10, 30}};
  for (const double hour : {0.0, 5.5, 12.0, 17.25}) {
    for (const int month : {1, 3, 6, 9, 12}) {
      const double jd = geo::julian_day(2024, month, 15, hour * 3600);
      for (const auto& d : domains) {
        const double lon0 = 0.5 * (d.lon_lo + d.lon_hi), lat0 = 0.5 * (d.lat_lo + d.lat_hi);
        const auto sun = sun_for_domain(jd, d.lon_lo, d.lon_hi, d.lat_lo, d.lat_hi, lon0, lat0);
        ASSERT_EQ(sun.viewpoint, SunViewpoint::kSunniestPoint);
        EXPECT_GE(sun.latitude_deg, d.lat_lo);
        EXPECT_LE(sun.latitude_deg, d.lat_hi);
        EXPECT_GE(sun.longitude_deg, d.lon_lo - 1e-9);
        EXPECT_LE(sun.longitude_deg, d.lon_hi + 1e-9);
        double highest = -90;
        for (int i = 0; i <= 200; ++i) {
          for (int j = 0; j <= 100; ++j) {
            const double lon = d.lon_lo + (d.lon_hi - d.lon_lo) * i / 200.0;
            const double lat = d.lat_lo + (d.lat_hi - d.lat_lo) * j / 100.0;
            highest = std::max(highest, geo::solar_position(jd, lat, lon).elevation_deg);
          }
        }
        EXPECT_GE(sun.position.elevation_deg, highest - 1e-6)
            << "hour " << hour << " month " << month << " domain " << d.lon_lo << ".." << d.lon_hi;
        EXPECT_LE(sun.position.elevation_deg, highest + 1.5);  // lattice steps up to 1.8 degrees
      }
    }
  }
}

TEST(SunDirectionTest, DomainsUpToThirtyDegreesKeepTheCentre) {
  const double jd = geo::julian_day(2013, 4, 26, 0);
  const auto sun = sun_for_domain(jd, -5, 25, 40, 60, 10, 50);  // 30 degrees: local midnight
  EXPECT_EQ(sun.viewpoint, SunViewpoint::kDomainCentre);
  EXPECT_LT(sun.position.elevation_deg, 0);
  EXPECT_EQ(sun.latitude_deg, 50);
  EXPECT_EQ(sun.longitude_deg, 10);
  EXPECT_NE(describe_sun(sun).find("the true sun over the domain centre (50.00 N, 10.00 E)"),
            std::string::npos)
      << describe_sun(sun);
  // 31 degrees: the sunniest point, still below the horizon at that hour.
  const auto wide = sun_for_domain(jd, -5.5, 25.5, 40, 60, 10, 50);
  EXPECT_EQ(wide.viewpoint, SunViewpoint::kSunniestPoint);
  EXPECT_LT(wide.position.elevation_deg, 0);  // night everywhere in the domain stays night
  EXPECT_GT(wide.position.elevation_deg, sun.position.elevation_deg);
}

}  // namespace
}  // namespace strielad::view
