// SPDX-License-Identifier: Apache-2.0
#include "geo/solar_position.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strielad::geo {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double wrap360(double degrees) {
  const double r = std::fmod(degrees, 360.0);
  return r < 0 ? r + 360.0 : r;
}

}  // namespace

SolarPosition solar_position(double julian_day, double latitude_deg, double longitude_deg) {
  // Julian centuries from J2000.0 (Meeus 25.1).
  const double t = (julian_day - 2451545.0) / 36525.0;
  const double l0 = wrap360(280.46646 + t * (36000.76983 + t * 0.0003032));   // 25.2
  const double m = 357.52911 + t * (35999.05029 - t * 0.0001537);              // 25.3
  const double c = std::sin(m * kDeg) * (1.914602 - t * (0.004817 + t * 0.000014)) +
                   std::sin(2 * m * kDeg) * (0.019993 - t * 0.000101) +
                   std::sin(3 * m * kDeg) * 0.000289;                          // centre
  const double omega = 125.04 - 1934.136 * t;
  const double lambda = l0 + c - 0.00569 - 0.00478 * std::sin(omega * kDeg);  // apparent
  const double epsilon0 =
      23.0 + (26.0 + (21.448 - t * (46.8150 + t * (0.00059 - t * 0.001813))) / 60.0) / 60.0;  // 22.2
  const double epsilon = epsilon0 + 0.00256 * std::cos(omega * kDeg);          // 25.8
  const double sin_lambda = std::sin(lambda * kDeg);
  const double alpha = std::atan2(std::cos(epsilon * kDeg) * sin_lambda, std::cos(lambda * kDeg));
  const double delta = std::asin(std::sin(epsilon * kDeg) * sin_lambda);

  // Greenwich mean sidereal time (12.4), then the local hour angle.
  const double d = julian_day - 2451545.0;
  const double gmst = wrap360(280.46061837 + 360.98564736629 * d + t * t * (0.000387933 - t / 38710000.0));
  double hour_angle = wrap360(gmst + longitude_deg - alpha / kDeg);
  if (hour_angle > 180) hour_angle -= 360;

  const double phi = latitude_deg * kDeg, h = hour_angle * kDeg;
  const double east = -std::cos(delta) * std::sin(h);
  const double north = std::sin(delta) * std::cos(phi) - std::cos(delta) * std::sin(phi) * std::cos(h);
  const double up = std::sin(delta) * std::sin(phi) + std::cos(delta) * std::cos(phi) * std::cos(h);

  SolarPosition p;
  p.declination_deg = delta / kDeg;
  p.right_ascension_deg = wrap360(alpha / kDeg);
  p.hour_angle_deg = hour_angle;
  p.elevation_deg = std::asin(std::clamp(up, -1.0, 1.0)) / kDeg;
  p.azimuth_deg = wrap360(std::atan2(east, north) / kDeg);
  const double length = std::sqrt(east * east + north * north + up * up);
  p.east_north_up = {east / length, north / length, up / length};
  return p;
}

}  // namespace strielad::geo
