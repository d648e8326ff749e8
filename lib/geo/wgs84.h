// SPDX-License-Identifier: Apache-2.0
// The WGS84 ellipsoid's closed form: geodetic longitude, latitude and height
// to earth-centred, earth-fixed (ECEF) positions (x towards 0 N 0 E, y towards 0 N 90 E,
// z towards the north pole) and the radii of curvature. One formula for the ECEF output
// frame of extraction (extract/output_frame.h, in metres) and the viewer's globe
// (lod/wgs84_globe.h, in kilometres): lengths come in the unit of the semi-major axis
// given, so that neither converts units on the way.
#pragma once

#include <array>
#include <cmath>
#include <numbers>

namespace strielad::geo {

inline constexpr double kWgs84SemiMajorM = 6378137.0;
inline constexpr double kWgs84Flattening = 1.0 / 298.257223563;
inline constexpr double kWgs84E2 = kWgs84Flattening * (2.0 - kWgs84Flattening);
inline constexpr double kWgs84SemiMinorM = kWgs84SemiMajorM * (1.0 - kWgs84Flattening);

// The map's terms at one longitude and latitude (all but the height), for callers that
// also need its derivatives.
struct EcefTerms {
  double sl, cl, so, co;  // sin and cos of the latitude and of the reduced longitude
  double w, n;            // sqrt(1 - e2 sin^2 lat); the prime vertical radius a / w
  double a;               // the semi-major axis, in the unit of every length here
  // The meridional radius of curvature a (1 - e2) / w^3.
  double meridional_radius() const { return a * (1.0 - kWgs84E2) / (w * w * w); }
};

// Degrees in; lengths in the unit of `semi_major` (metres by default). The longitude is
// reduced exactly to [-180, 180] first, so that a meridian and the same meridian a turn on
// (a periodic grid's seam) give the same bits.
inline EcefTerms ecef_terms(double lon_deg, double lat_deg,
                            double semi_major = kWgs84SemiMajorM) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  const double lr = std::remainder(lon_deg, 360.0);
  EcefTerms e{};
  e.sl = std::sin(lat_deg * kDeg);
  e.cl = std::cos(lat_deg * kDeg);
  e.so = std::sin(lr * kDeg);
  e.co = std::cos(lr * kDeg);
  e.w = std::sqrt(1.0 - kWgs84E2 * e.sl * e.sl);
  e.n = semi_major / e.w;
  e.a = semi_major;
  return e;
}

// ECEF position at height `h` above the ellipsoid (the unit of the terms' semi-major axis).
inline std::array<double, 3> ecef_position(const EcefTerms& e, double h) {
  return {(e.n + h) * e.cl * e.co, (e.n + h) * e.cl * e.so, (e.n * (1.0 - kWgs84E2) + h) * e.sl};
}

}  // namespace strielad::geo
