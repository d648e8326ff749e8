// SPDX-License-Identifier: Apache-2.0
// The WGS84 ellipsoid in kilometres, for the viewer's globe frame (lod/world_frame.h):
// earth-centred, earth-fixed (ECEF) positions of geodetic longitude, latitude and height,
// the inverse, and the local east/north/up directions. The closed form of geo/wgs84.h, the
// ECEF output frame's of extraction, without PROJ.
#pragma once

#include "geo/wgs84.h"
#include "lod/geometry.h"

namespace strielad::lod {

// geo::kWgs84SemiMajorM in km, written out: 6378137 * 1e-3 is not exactly 6378.137.
inline constexpr double kWgs84SemiMajorKm = 6378.137;
inline constexpr double kWgs84E2 = geo::kWgs84E2;
inline constexpr double kWgs84SemiMinorKm = kWgs84SemiMajorKm * (1.0 - geo::kWgs84Flattening);

// Geodetic longitude and latitude (degrees), height above the ellipsoid (km) to ECEF km:
// x towards (0 N, 0 E), y towards (0 N, 90 E), z towards the north pole.
Vec3 geodetic_to_ecef_km(double lon_deg, double lat_deg, double height_km);

struct Geodetic {
  double lon_deg = 0, lat_deg = 0, height_km = 0;
};
// The inverse (Bowring's start and two Newton steps: below a micrometre for heights
// between -1000 and +100000 km). Longitude in (-180, 180]; the centre gives 0, 90, -b.
Geodetic ecef_km_to_geodetic(const Vec3& p);

// Unit vectors at (lon, lat): east, north and up (the ellipsoid normal) in ECEF.
struct LocalAxes {
  Vec3 east, north, up;
};
LocalAxes local_axes(double lon_deg, double lat_deg);

// Radii of curvature (km) at latitude `lat_deg`: prime vertical N and meridional M.
double prime_vertical_radius_km(double lat_deg);
double meridional_radius_km(double lat_deg);

}  // namespace strielad::lod
