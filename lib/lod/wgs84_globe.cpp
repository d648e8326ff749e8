// SPDX-License-Identifier: Apache-2.0
#include "lod/wgs84_globe.h"

#include <cmath>
#include <numbers>

namespace strielad::lod {
namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}  // namespace

double prime_vertical_radius_km(double lat_deg) {
  return geo::ecef_terms(0.0, lat_deg, kWgs84SemiMajorKm).n;
}

double meridional_radius_km(double lat_deg) {
  return geo::ecef_terms(0.0, lat_deg, kWgs84SemiMajorKm).meridional_radius();
}

Vec3 geodetic_to_ecef_km(double lon_deg, double lat_deg, double h) {
  return geo::ecef_position(geo::ecef_terms(lon_deg, lat_deg, kWgs84SemiMajorKm), h);
}

Geodetic ecef_km_to_geodetic(const Vec3& p) {
  const double a = kWgs84SemiMajorKm, b = kWgs84SemiMinorKm, e2 = kWgs84E2;
  const double r = std::hypot(p[0], p[1]);
  Geodetic g;
  g.lon_deg = r > 0 ? std::atan2(p[1], p[0]) / kDeg : 0.0;
  if (r == 0 && p[2] == 0) {
    g.lat_deg = 90.0;
    g.height_km = -b;
    return g;
  }
  // Bowring's parametric start, then Newton on the latitude.
  const double ep2 = (a * a - b * b) / (b * b);
  const double beta = std::atan2(a * p[2], b * r);
  double lat = std::atan2(p[2] + ep2 * b * std::pow(std::sin(beta), 3),
                          r - e2 * a * std::pow(std::cos(beta), 3));
  for (int it = 0; it < 3; ++it) {
    const double s = std::sin(lat), c = std::cos(lat);
    const double n = a / std::sqrt(1.0 - e2 * s * s);
    // f(lat) = r sin(lat) - z cos(lat) - e2 n sin(lat) cos(lat) = 0 on the normal.
    const double f = r * s - p[2] * c - e2 * n * s * c;
    const double df = r * c + p[2] * s - e2 * n * (c * c - s * s);
    if (!(std::fabs(df) > 0)) break;
    lat -= f / df;
  }
  const double s = std::sin(lat), c = std::cos(lat);
  const double n = a / std::sqrt(1.0 - e2 * s * s);
  g.lat_deg = lat / kDeg;
  // Of the two forms, the one better conditioned at this latitude.
  if (std::fabs(c) > 0.5) {
    g.height_km = r / c - n;
  } else {
    g.height_km = p[2] / s - n * (1.0 - e2);
  }
  return g;
}

LocalAxes local_axes(double lon_deg, double lat_deg) {
  const double lon = std::remainder(lon_deg, 360.0) * kDeg, lat = lat_deg * kDeg;
  const double so = std::sin(lon), co = std::cos(lon), sl = std::sin(lat), cl = std::cos(lat);
  return {{-so, co, 0.0}, {-sl * co, -sl * so, cl}, {cl * co, cl * so, sl}};
}

}  // namespace strielad::lod
