// SPDX-License-Identifier: Apache-2.0
// What a variable's x and y axes are on the Earth, decided from their CF metadata and the
// variable's grid mapping (pure: no netCDF calls):
// - longitude and latitude (degrees_east/north, standard_name longitude/latitude, or a
//   conventional name): kept as they are; a longitude axis written wrapped at the
//   antimeridian is made continuous, and one that goes round the Earth becomes periodic
//   (its first meridian is repeated at the end, 360 degrees on: formats/store.md);
// - map-projection coordinates with a grid mapping (rotated-pole grid_longitude and
//   grid_latitude in degrees, projection_x/y_coordinate in metres or km): kinds
//   projection_x and projection_y, placed by the mapping's PROJ pipeline;
// - projection coordinates without a grid mapping: a Cartesian grid in metres with no
//   place on the Earth (allowed, and said in a note);
// - rotated-pole coordinates without a grid mapping: refused, as nothing would say where
//   the pole is. Nothing is ever silently treated as geographic.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grid/axis.h"
#include "grid/grid_mapping.h"

namespace strielad::ingest {

struct HorizontalAxes {
  std::optional<GridMapping> mapping;  // with its PROJ pipeline
  std::size_t source_nx = 0;           // samples per row in the source (x.size() before any
                                       // repeated meridian was appended)
  std::vector<std::string> notes;      // what was decided, for the log
};

// `x` and `y` arrive with their values, name, units and standard_name (kind ignored);
// `x_axis_attribute`/`y_axis_attribute`: their CF `axis` attributes. `what` names the
// file and variable in messages.
// \error kUnsupported / kInvalidInput naming the axis, the mapping and what is wrong:
// rotated coordinates without a grid mapping, a grid mapping on longitude/latitude axes
// (other than latitude_longitude), mixed axes (one geographic, one projected), and
// whatever geo::cf_grid_mapping_proj refuses.
HorizontalAxes place_horizontal_axes(Axis& x, Axis& y, std::optional<GridMapping> mapping,
                                     std::string_view what);

}  // namespace strielad::ingest
