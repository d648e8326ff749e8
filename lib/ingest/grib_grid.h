// SPDX-License-Identifier: Apache-2.0
// Where a GRIB message's samples lie on the Earth, from its grid definition, as the same
// axes and CF grid mapping a netCDF input would give (ingest/horizontal_axes.h):
// - regular_ll and regular_gg: longitude and latitude axes (Gaussian latitudes as ecCodes
//   computes them), evenly from the first to the last point, with a note when the
//   message's increments say otherwise;
// - rotated_ll: rotated-pole axes in degrees with a rotated_latitude_longitude mapping
//   (grid north pole = the message's southern pole turned half round);
// - lambert, polar_stereographic, mercator: projection axes in metres with the CF
//   mapping (lambert_conformal_conic, polar_stereographic, mercator); the first grid
//   point projected by PROJ, then DxInMetres and DyInMetres steps from it.
// Scanning follows the GRIB specification on every grid type (ecCodes 2.28 ignores it on
// polar stereographic grids). The Earth's figure is the message's (GRIB 2
// shapeOfTheEarth, GRIB 1 earthIsOblate),
// written into the mapping. Axes follow the message's scanning (x along i, y along j),
// so values are stored in the order they come.
#pragma once

#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "grid/axis.h"
#include "ingest/eccodes_call.h"
#include "ingest/horizontal_axes.h"

namespace strielad::ingest {

// The grid definition keys of one message, as ecCodes names them (NaN: absent).
struct GribGridKeys {
  static constexpr double kAbsent = std::numeric_limits<double>::quiet_NaN();
  long edition = 2;
  std::string grid_type;  // gridType
  long ni = 0, nj = 0;    // Ni, Nj (Nx, Ny on projected grids)
  bool i_scans_negatively = false, j_scans_positively = false;
  bool j_points_are_consecutive = false, alternative_row_scanning = false;
  double lat_first = kAbsent, lon_first = kAbsent, lat_last = kAbsent, lon_last = kAbsent;
  // Regular and rotated lon/lat: the increments, when the message gives them (checked
  // against the first and last points).
  double di_degrees = kAbsent, dj_degrees = kAbsent;
  std::vector<double> gaussian_latitudes;  // regular_gg: distinctLatitudes
  // rotated_ll
  double south_pole_lat = kAbsent, south_pole_lon = kAbsent, rotation_angle = 0;
  // lambert, polar_stereographic, mercator
  double lad = kAbsent, lov = kAbsent, latin1 = kAbsent, latin2 = kAbsent;
  double dx_metres = kAbsent, dy_metres = kAbsent;
  long projection_centre = 0;  // projectionCentreFlag: 128 south pole, 64 bipolar
  // The Earth: GRIB 2 code table 3.2 (GRIB 1 earthIsOblate 0 is shape 0, 1 is shape 2);
  // radius for shape 1, the axes in metres for shapes 3 and 7.
  long shape_of_the_earth = 0;
  double radius = kAbsent, major_axis = kAbsent, minor_axis = kAbsent;
};

// The caller holds eccodes_mutex(). `what` names the file and message in messages.
GribGridKeys read_grib_grid_keys(const GribHandle& message, std::string_view what);

struct GribGrid {
  Axis x, y;
  HorizontalAxes placement;  // mapping (with its PROJ pipeline), notes
};

// \error kUnsupported naming the grid type and what to do for reduced (quasi-regular),
// spherical-harmonic and other grid types, alternative row scanning, j-consecutive
// points, a rotation angle, bipolar Lambert projections and unknown Earth shapes;
// kInvalidInput naming the key when one is absent or out of range.
GribGrid grib_grid(const GribGridKeys& keys, std::string_view what);

}  // namespace strielad::ingest
