// SPDX-License-Identifier: Apache-2.0
// CF grid mappings (conventions appendix F) translated into PROJ pipelines that place a
// grid's axis coordinates on the Earth: (x, y) in the axes' own units to (longitude,
// latitude) in degrees. A pure function of the attributes: no PROJ call here
// (geo/grid_projection.h runs the pipeline).
//
// | grid_mapping_name | PROJ | axes |
// |---|---|---|
// | rotated_latitude_longitude | ob_tran, o_proj=longlat, o_lat_p, o_lon_p, lon_0 = 180 + pole longitude | degrees |
// | lambert_conformal_conic | lcc | length |
// | polar_stereographic | stere, lat_0 = +-90, lat_ts or k_0 | length |
// | stereographic | stere | length |
// | transverse_mercator | tmerc | length |
// | mercator | merc, lat_ts or k_0 | length |
// | lambert_azimuthal_equal_area | laea | length |
// | albers_conical_equal_area | aea | length |
// | azimuthal_equidistant | aeqd | length |
// | orthographic | ortho | length |
// | lambert_cylindrical_equal_area | cea, lat_ts or k_0 | length |
// | sinusoidal | sinu | length |
// | latitude_longitude | none: the axes are longitude and latitude | degrees |
//
// The figure of the Earth: earth_radius (a sphere), semi_major_axis with
// semi_minor_axis or inverse_flattening (0 for a sphere), semi_major_axis alone (a
// sphere); none of them: WGS84. A rotated pole is a rotation of the sphere and needs no
// figure. Longitudes and latitudes come out on that figure and are used as WGS84
// geodetic coordinates (no datum shift), as models and their users treat them.
// Axes in kilometres are scaled to metres first; false_easting and false_northing are in
// metres as CF defines them.
#pragma once

#include <string>
#include <string_view>

#include "grid/axis.h"
#include "grid/grid_mapping.h"

namespace strielad::geo {

// The PROJ pipeline for `mapping` (its name and attributes) on axes `x` and `y`;
// "" for latitude_longitude (the axes are geographic already). `what` names the variable
// and file in messages.
// \error kUnsupported naming the grid_mapping_name (and listing those translated) when
// it is not in the table above, and naming the axis when its units do not suit the
// mapping (degrees for a rotated pole, a length otherwise).
// \error kInvalidInput naming the attribute when a required one is missing, not a
// number, not finite or out of range (a latitude beyond +-90, a radius <= 0).
std::string cf_grid_mapping_proj(const GridMapping& mapping, const Axis& x, const Axis& y,
                                 std::string_view what);

// The grid_mapping_name values translated, in the table's order.
std::string_view supported_grid_mappings();

}  // namespace strielad::geo
