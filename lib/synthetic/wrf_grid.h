// SPDX-License-Identifier: Apache-2.0
// The horizontal grid of the WRF-like sample (wrf_like_file.h): WRF's Arakawa C grid on
// a Lambert conformal projection (MAP_PROJ = 1, true latitudes 30 and 60 N) of WRF's
// sphere (radius 6370 km), centred on the sample's lon/lat area over Germany
// (sample_grid.h) with DX and DY chosen so that nx x ny mass points span about that area.
// Mass point (i, j) sits at x = (i - (nx - 1) / 2) * DX, y = (j - (ny - 1) / 2) * DY from
// the centre; U points half a cell west and east of them (nx + 1 per row), V points half
// a cell south and north (ny + 1 per column). Longitudes and latitudes come from PROJ.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace strielad::synthetic {

inline constexpr double kWrfEarthRadius = 6370000.0;  // m, WRF's sphere
inline constexpr double kWrfTrueLat1 = 30.0, kWrfTrueLat2 = 60.0;

// The PROJ string of WRF's Lambert conformal projection: "+proj=lcc +lat_1=30 +lat_2=60
// +lat_0=<cen_lat> +lon_0=<stand_lon> +R=6370000 +units=m".
std::string wrf_lcc_proj_string(double cen_lat, double stand_lon);

struct WrfGrid {
  std::size_t nx = 0, ny = 0;       // mass points
  double dx = 0, dy = 0;            // m, whole metres
  double cen_lat = 0, cen_lon = 0;  // degrees; STAND_LON = cen_lon
  std::string proj;                 // wrf_lcc_proj_string(cen_lat, cen_lon)
  // Projected coordinates (m from the centre) of the mass points' columns and rows.
  std::vector<double> x, y;
  // Longitude and latitude (degrees) of the mass points (ny x nx), the U points
  // (ny x (nx + 1)) and the V points ((ny + 1) x nx), x fastest.
  std::vector<double> lon, lat, lon_u, lat_u, lon_v, lat_v;

  // x/y in m of mass (i, j) and of the staggered points.
  double x_at(double i) const;
  double y_at(double j) const;
};

// The grid of nx x ny (>= 1) mass points. \error kUnsupported when PROJ rejects the
// projection.
WrfGrid wrf_grid(std::size_t nx, std::size_t ny);

// The cosine and sine of the angle between the grid's x axis and east at longitude
// `lon` (WRF's COSALPHA, SINALPHA): earth-relative u = U cos - V sin, v = V cos + U sin.
std::pair<double, double> wrf_rotation(const WrfGrid& grid, double lon);

}  // namespace strielad::synthetic
