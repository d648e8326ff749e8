// SPDX-License-Identifier: Apache-2.0
// The CF grid mapping rotated_latitude_longitude (CF conventions, appendix F): a
// latitude/longitude grid whose north pole sits at (grid_north_pole_longitude,
// grid_north_pole_latitude) of the true sphere, as COSMO, CCLM and the ICON-LAM output
// on rotated grids use. Conversions both ways by the pole formula (spherical rotation
// about the y axis and the z axis, the form of COSMO's utilities rlarot2rla/phirot2phi),
// in degrees; geographic longitudes come out in (-180, 180].
#pragma once

namespace strielad::geo {

struct RotatedPole {
  double pole_lat = 90;  // grid_north_pole_latitude, degrees
  double pole_lon = 0;   // grid_north_pole_longitude, degrees
  // north_pole_grid_longitude (rarely used): longitude of the true pole in the rotated grid.
  double north_pole_grid_lon = 0;
};

struct LonLat {
  double lon = 0, lat = 0;  // degrees
};

// Rotated (rlon, rlat) to geographic (lon, lat).
LonLat rotated_to_geographic(const RotatedPole& pole, double rlon, double rlat);
// Geographic (lon, lat) to rotated (rlon, rlat), the inverse (rlon in (-180, 180]).
LonLat geographic_to_rotated(const RotatedPole& pole, double lon, double lat);

}  // namespace strielad::geo
