// SPDX-License-Identifier: Apache-2.0
// What places a GRIB catalog's model levels, found among the fields of its inputs:
// hybrid levels (IFS, ERA5) by pressure from their `pv` coefficients and the surface
// pressure (lnsp or sp); COSMO/ICON generalVerticalLayer and generalVertical levels by the
// height of their half levels (HHL). A surface height (orog, HSURF, h, or the surface
// geopotential z) comes with either. See docs/input-data.md, "GRIB".
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "ingest/grib_scan.h"
#include "ingest/input_catalog.h"

namespace strielad::ingest {

// One chosen variable in one input: scans[file].variables holds *variable.
struct GribVariablePart {
  std::size_t file = 0;
  const GribVariable* variable = nullptr;
};

// Whether a 3-D field only places the levels (HHL) or is the surface pressure: not
// chosen when the variables are not asked for.
bool grib_field_places_levels(std::string_view short_name);

// Sets c.vertical_geometry, c.surface and c.grib_fields for a catalog whose grid, z axis
// (from `chosen`, all on one type of level) and time axis are set. Nothing for levels
// other than hybrid, generalVertical and generalVerticalLayer, nor for hybrid levels
// without pv, nor for COSMO levels without HHL (their z axis stays level numbers).
// \error kInvalidInput naming both messages when two chosen messages have different pv,
// a level number outside the pv's 1..N, hybrid levels with pv but no lnsp or sp, the
// catalog time step (and validity time) at which lnsp, sp or a varying HHL lacks a
// message, HHL without a half level that a level needs, and a placing field on another
// grid than the variables.
void detect_grib_vertical_geometry(const std::vector<GribScan>& scans,
                                   const std::vector<GribVariablePart>& chosen, InputCatalog& c);

}  // namespace strielad::ingest
