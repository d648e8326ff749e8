// SPDX-License-Identifier: Apache-2.0
// Which way a rectilinear grid's index directions turn on the Earth: the sign of the
// determinant of d(east, north) / d(i, j), the horizontal part of a store geometry's
// `orientation` (formats/store.md, "Grid geometry (version 5)").
#pragma once

#include <optional>

#include "grid/axis.h"
#include "grid/grid_mapping.h"

namespace strielad::geo {

// +1 or -1 for axes x, y (longitude and latitude, or projection coordinates placed by
// `mapping`'s PROJ pipeline, evaluated at the grid's centre), from the axes' directions
// and the map's Jacobian. Cartesian axes without a mapping count as east and north.
// \error kUnsupported naming the mapping when its Jacobian at the centre is singular or
// not finite.
int horizontal_orientation(const Axis& x, const Axis& y, const std::optional<GridMapping>& mapping);

}  // namespace strielad::geo
