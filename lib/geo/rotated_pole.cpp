// SPDX-License-Identifier: Apache-2.0
#include "geo/rotated_pole.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strielad::geo {
namespace {

constexpr double kRad = std::numbers::pi / 180.0;

double wrap180(double deg) {
  double d = std::fmod(deg + 180.0, 360.0);
  if (d <= 0) d += 360.0;
  return d - 180.0;
}

struct Unit {
  double x, y, z;
};
Unit unit(double lon_deg, double lat_deg) {
  const double lon = lon_deg * kRad, lat = lat_deg * kRad;
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}
LonLat angles(const Unit& u) {
  return {std::atan2(u.y, u.x) / kRad, std::asin(std::clamp(u.z, -1.0, 1.0)) / kRad};
}
Unit rotate_y(const Unit& u, double deg) {
  const double c = std::cos(deg * kRad), s = std::sin(deg * kRad);
  return {c * u.x + s * u.z, u.y, -s * u.x + c * u.z};
}

}  // namespace

// The rotated frame is the geographic one turned so that the pole (pole_lon, pole_lat)
// becomes (0, 90) and the meridian pole_lon + 180 becomes the rotated meridian 0:
// geographic = Rz(pole_lon + 180) Ry(-(90 - pole_lat)) Rz(-north_pole_grid_lon) rotated.
LonLat rotated_to_geographic(const RotatedPole& pole, double rlon, double rlat) {
  Unit u = unit(rlon - pole.north_pole_grid_lon, rlat);
  u = rotate_y(u, -(90.0 - pole.pole_lat));
  const LonLat g = angles(u);
  return {wrap180(g.lon + pole.pole_lon + 180.0), g.lat};
}

LonLat geographic_to_rotated(const RotatedPole& pole, double lon, double lat) {
  Unit u = unit(lon - pole.pole_lon - 180.0, lat);
  u = rotate_y(u, 90.0 - pole.pole_lat);
  const LonLat r = angles(u);
  return {wrap180(r.lon + pole.north_pole_grid_lon), r.lat};
}

}  // namespace strielad::geo
