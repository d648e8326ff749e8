// SPDX-License-Identifier: Apache-2.0
// Exact comparison of rectilinear axes (values, names, units) with a message that says
// what differs first, for the errors about inputs whose grids do not match.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "grid/axis.h"

namespace strielad::ingest {

// nullopt when `got` equals `want` (name, units and every value); else the first
// difference as "axis 'lat' has 96 values but <want_where> has 64",
// "axis 'lev_2' has 151 values but axis 'lev' in <want_where> has 150",
// "axis 'lev' has units 'hPa' but <want_where> has 'Pa'" or
// "axis 'lat' value[3] = 1.5 but <want_where> has 1.25".
std::optional<std::string> axis_difference(const Axis& got, const Axis& want,
                                           std::string_view want_where);

// The first difference among x, y and z (longitude, latitude, vertical).
std::optional<std::string> grid_difference(const Axis& got_x, const Axis& got_y,
                                           const Axis& got_z, const Axis& want_x,
                                           const Axis& want_y, const Axis& want_z,
                                           std::string_view want_where);

}  // namespace strielad::ingest
