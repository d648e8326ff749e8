// SPDX-License-Identifier: Apache-2.0
// The variables of a WRF history file (wrf_grid_reader.h recognises one), classified
// without the curvilinear path: fields on (Time, bottom_top, south_north, west_east) are
// on the grid (kGrid3D); U, V and W (one of the three dimensions *_stag) too, read
// destaggered onto the mass points (wrf_destagger.h). Everything else (2-D fields such
// as HGT, soil levels, XLAT/XLONG, ZNU, Times) is kNotGridded with the reason.
// T, WRF's perturbation potential temperature (theta - 300 K) in K, is offered as the
// potential temperature `theta` = T + 300 K (VariableMeta::source_variable and
// value_offset), listed where T is and taken by default instead of T; T itself is
// converted when asked for by name. A file that has a variable named theta gets none.
#pragma once

#include <string>
#include <vector>

#include "ingest/file_scan.h"

namespace strielad::ingest {

inline constexpr const char* kWrfThetaName = "theta";

// Caller holds netcdf_mutex(). Throws what read_wrf_layout throws.
std::vector<ScannedVariable> scan_wrf_variables(int ncid, const std::string& file);

}  // namespace strielad::ingest
