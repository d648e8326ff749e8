// SPDX-License-Identifier: Apache-2.0
// Where the sun is, for the viewer's lighting: the low-precision solar coordinates of J. Meeus,
// "Astronomical Algorithms", 2nd ed. (1998), chapter 25 (the algorithm of NOAA's solar
// calculator), with the Greenwich mean sidereal time of chapter 12 (eq. 12.4).
//
// Accuracy: Meeus gives 0.01 degree for the sun's apparent coordinates between 1950
// and 2050 (tests/geo/solar_position_test.cpp checks his example 25.a and the NREL
// SPA example of Reda & Andreas (2004) to 0.02 and 0.05 degree). Not modelled, each
// below what a rendered sun direction can show: the difference between UT and
// dynamical time (about 69 s: 0.003 degree of solar longitude), atmospheric
// refraction (0.5 degree at the horizon, 0.02 degree at 40 degrees elevation) and
// parallax (0.0024 degree).
#pragma once

#include <array>

namespace strielad::geo {

struct SolarPosition {
  double declination_deg = 0;
  double right_ascension_deg = 0;  // [0, 360)
  double hour_angle_deg = 0;       // local, (-180, 180], positive west (afternoon)
  double elevation_deg = 0;        // above the horizon, no refraction
  double azimuth_deg = 0;          // clockwise from north, [0, 360)
  // Unit vector towards the sun in the local east-north-up frame.
  std::array<double, 3> east_north_up{};
};

// The sun seen from latitude/longitude (degrees, east positive) at `julian_day` (UTC).
SolarPosition solar_position(double julian_day, double latitude_deg, double longitude_deg);

}  // namespace strielad::geo
