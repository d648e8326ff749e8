// SPDX-License-Identifier: Apache-2.0
// One catalog from GRIB and netCDF inputs of one conversion: the catalog of the GRIB files
// (ingest/grib_catalog.h) and that of the netCDF files, joined only when they agree
// exactly: the same horizontal axes (kind, units and every value, as grid_compare compares
// netCDF files), the same grid mapping (name and PROJ pipeline) or none on either side,
// the same vertical axis (kind, units, values), and the same time steps once expressed in
// the time units of the first input's side (ingest/time_reconciliation.h). Every variable
// comes from one side; levels that need a vertical geometry (terrain-following, hybrid)
// or a surface field, and curvilinear grids, are not mixed.
#pragma once

#include "ingest/input_catalog.h"

namespace strielad::ingest {

// `grib` and `netcdf` are built without a step range; ScanOptions::first_step/last_step
// of `options` then select among the joined steps. `grib_first`: the first input is GRIB,
// so the GRIB side's grid, time units and variables come first.
// \error kInvalidInput naming a file of each side and what differs (an axis and its first
// differing value, the grid mappings, a time step one side lacks, a variable on both
// sides); kUnsupported for a vertical geometry, a surface field or a curvilinear grid;
// kInvalidArgument for a step range outside the joined steps.
InputCatalog merge_grib_and_netcdf(const InputCatalog& grib, const InputCatalog& netcdf,
                                   bool grib_first, const ScanOptions& options);

}  // namespace strielad::ingest
