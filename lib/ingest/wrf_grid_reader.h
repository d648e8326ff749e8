// SPDX-License-Identifier: Apache-2.0
// The grid of a WRF ARW history file (wrfout_d0*), described from its global attributes
// instead of its 2-D XLAT/XLONG: MAP_PROJ 1 (Lambert conformal: TRUELAT1, TRUELAT2,
// STAND_LON), 2 (polar stereographic: TRUELAT1, STAND_LON), 3 (Mercator: TRUELAT1,
// STAND_LON) become a CF-named GridMapping (lambert_conformal_conic, polar_stereographic,
// mercator) on WRF's sphere (earth_radius 6370000 m) with projection x/y axes in metres;
// MAP_PROJ 6 with POLE_LAT 90 (a regular latitude/longitude grid) becomes longitude and
// latitude axes. Mass point (i, j) sits at (x0 + i DX, y0 + j DY): x0 and y0 are the mean
// over every mass point of its projected XLONG/XLAT less (i DX, j DY) (so the float
// rounding of XLAT/XLONG averages out), and every mass point of every step must then lie
// within max(0.5 m, 1e-3 of a cell) of its place (in degrees of a cell for MAP_PROJ 6).
// The vertical axis is bottom_top, the mass levels' index 0..nz-1 counted from the
// ground (a model level, never a height: PH + PHB place the levels).
#pragma once

#include <optional>
#include <string>

#include "grid/axis.h"
#include "grid/grid_mapping.h"
#include "ingest/file_scan.h"

namespace strielad::ingest {

inline constexpr double kWrfEarthRadius = 6370000.0;  // m, WRF's sphere
inline constexpr double kWrfGravity = 9.81;           // m s-2, WRF's g

struct WrfLayout {
  Axis x, y, z;                          // mass points: west_east, south_north, bottom_top
  std::optional<GridMapping> mapping;    // none for MAP_PROJ 6 (longitude/latitude axes)
  std::optional<TimeCoordinate> time;    // from Times; none without a Time dimension
  double max_deviation = 0;              // of XLAT/XLONG from the grid, in axis units
};

// Whether the open file `ncid` is WRF output: a global TITLE containing "OUTPUT FROM
// WRF", or the dimensions west_east, south_north and bottom_top with a global MAP_PROJ.
bool is_wrf_file(int ncid);

// Caller holds netcdf_mutex(). `file` names the file in messages.
// \error kUnsupported for a MAP_PROJ not translated (a rotated latitude/longitude grid:
// MAP_PROJ 6 with POLE_LAT != 90) ; kInvalidInput naming the attribute or variable at
// fault (missing, not finite), and naming the largest deviation, its mass point and step
// when XLAT/XLONG do not lie on the grid the attributes describe (a moving nest, edited
// coordinates, inconsistent attributes).
WrfLayout read_wrf_layout(int ncid, const std::string& file);

}  // namespace strielad::ingest
