// SPDX-License-Identifier: Apache-2.0
// Reads a data variable's CF grid mapping: the `grid_mapping` attribute (the short form
// "rotated_pole" or the extended form "crs: x y") and every attribute of the variable it
// names. Calls netCDF: the caller holds netcdf_mutex().
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "grid/grid_mapping.h"

namespace strielad::ingest {

// The grid mapping of variable `varid` in group `grpid`, or nothing when it has no
// `grid_mapping` attribute. `proj` is left empty (geo/cf_grid_mapping.h fills it).
// \error kInvalidInput naming `what` (file and variable) when the attribute names a
// variable that is not in the group or its ancestors, has more than one mapping, or the
// mapping variable has no grid_mapping_name.
std::optional<GridMapping> read_grid_mapping(int grpid, int varid, std::string_view what);

}  // namespace strielad::ingest
