// SPDX-License-Identifier: Apache-2.0
// The sun's position (lib/geo/solar_position.h) against published reference values:
// Meeus, "Astronomical Algorithms" example 25.a, and the NREL SPA example of Reda &
// Andreas (2004, table A4.1); and the geometry of the east-north-up direction.
#include <gtest/gtest.h>

#include <cmath>

#include "geo/cf_time.h"
#include "geo/solar_position.h"

namespace strielad::geo {
namespace {

TEST(SolarPositionTest, MeeusExample25a) {
  // 1992 October 13.0 (TD; UT differs by a minute, 0.0007 degree of the sun's motion).
  const SolarPosition p = solar_position(2448908.5, 0, 0);
  EXPECT_NEAR(p.right_ascension_deg, 198.38083, 0.005);  // 13h 13m 31.4s
  EXPECT_NEAR(p.declination_deg, -7.78507, 0.005);       // -7 47' 06"
  // His accurate values (VSOP87): 198.378178 and -7.783871 degrees.
  EXPECT_NEAR(p.right_ascension_deg, 198.378178, 0.02);
  EXPECT_NEAR(p.declination_deg, -7.783871, 0.02);
}

TEST(SolarPositionTest, NrelSpaExample) {
  // 2003-10-17 12:30:30 at UTC-7, Golden, Colorado (39.742476 N, 105.1786 W). SPA:
  // zenith 50.11162 degrees (with 0.016 degree of refraction), azimuth 194.34024.
  const double jd = julian_day(2003, 10, 17, (12 + 7) * 3600.0 + 30 * 60 + 30);
  const SolarPosition p = solar_position(jd, 39.742476, -105.1786);
  EXPECT_NEAR(90.0 - p.elevation_deg, 50.11162 + 0.016, 0.05);
  EXPECT_NEAR(p.azimuth_deg, 194.34024, 0.05);
  EXPECT_GT(p.hour_angle_deg, 0);  // after local noon
}

TEST(SolarPositionTest, DirectionGeometry) {
  // Equinox noon over Greenwich: almost overhead on the equator, and below the horizon
  // on the opposite meridian.
  const double jd = julian_day(2000, 3, 20, 12 * 3600.0);
  const SolarPosition noon = solar_position(jd, 0, 0);
  EXPECT_GT(noon.elevation_deg, 88.0);
  const SolarPosition night = solar_position(jd, 0, 180);
  EXPECT_LT(night.elevation_deg, -88.0);
  // Morning in Europe: the sun in the east, rising; evening in the west.
  const SolarPosition morning = solar_position(julian_day(2013, 4, 26, 6 * 3600.0), 51, 9.5);
  EXPECT_GT(morning.east_north_up[0], 0.5);
  EXPECT_GT(morning.elevation_deg, 0);
  EXPECT_LT(morning.hour_angle_deg, 0);
  const SolarPosition evening = solar_position(julian_day(2013, 4, 26, 17 * 3600.0), 51, 9.5);
  EXPECT_LT(evening.east_north_up[0], -0.5);
  for (const auto& p : {noon, night, morning, evening}) {
    const auto& v = p.east_north_up;
    EXPECT_NEAR(v[0] * v[0] + v[1] * v[1] + v[2] * v[2], 1.0, 1e-12);
    EXPECT_NEAR(std::asin(v[2]) * 180 / M_PI, p.elevation_deg, 1e-9);
  }
}

}  // namespace
}  // namespace strielad::geo
