// SPDX-License-Identifier: Apache-2.0
// Finding how a catalog's samples lie vertically when its z axis alone does not say
// (terrain-following levels), and the model's surface height, in its netCDF files:
//   1. an explicit height field: ScanOptions::height_var, else the one of z_mc, z_ifc,
//      HHL or PH + PHB the files hold (on the variables' levels or half levels);
//   2. a CF formula (formula_terms on the z coordinate variable);
//   3. the CCM attributes A_var, B_var, P0_var, PS_var (z coordinate or data variable).
// The surface: the orog term of a hybrid height formula, else HSURF, HGT, topography_c or
// orog on the grid's (y, x) with height units.
#pragma once

#include <optional>

#include "ingest/input_catalog.h"

namespace strielad::ingest {

struct VerticalDetection {
  std::optional<VerticalGeometrySource> geometry;
  std::optional<SurfaceSource> surface;
};

// `catalog`: scanned netCDF inputs with their time locations. Takes netcdf_mutex().
// \error kNotFound: height_var in no input file. kInvalidInput naming the file and
// variable: two automatic height candidates (suggesting --height-var); a source or term
// with the wrong dimensions or units; a formula term missing from formula_terms or a
// term variable missing from every file (suggesting --formula-term NAME=VALUE); a
// time-varying term missing for a time step. kUnsupported: a formula standard_name not
// supported (the message lists those that are). An atmosphere_ln_pressure_coordinate z
// axis places every sample itself (the scan made it a pressure axis: ln_pressure_axis.h).
// The variables that would place the levels rather than be data: ScanOptions::height_var,
// z_mc, z_ifc, HHL, PH and PHB.
std::vector<std::string> height_field_names(const ScanOptions& options);

VerticalDetection detect_vertical_geometry(const InputCatalog& catalog, const ScanOptions& options);

}  // namespace strielad::ingest
