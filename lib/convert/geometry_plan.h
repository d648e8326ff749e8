// SPDX-License-Identifier: Apache-2.0
// The manifest's grid geometry (formats/store.md, "Grid geometry (version 5)") for what
// the inputs hold: terrain-following levels as a per-sample height or pressure field, and
// the model's surface height.
#pragma once

#include <optional>

#include "format/geometry_file_format.h"
#include "format/manifest.h"
#include "ingest/input_catalog.h"

namespace strielad::build {

// +1 or -1: how the grid's index directions turn on the Earth (the sign of det
// d(east, north) / d(i, j)): a curvilinear grid's own, else geo::horizontal_orientation of
// the axes and grid mapping.
int horizontal_sign(const ingest::InputCatalog& catalog);

// The level-0 2-D longitude and latitude of a curvilinear catalog (no surface); empty
// arrays for a grid placed by its axes.
format::HorizontalCoordinates curvilinear_coordinates(const ingest::InputCatalog& catalog);

// None when the catalog has neither a curvilinear grid, a vertical geometry nor a surface. The field is stored
// as float32 with `codec`'s Blosc settings and the lorenzo3 predictor (heights and
// pressures are smooth); its orientation comes from horizontal_sign and the direction
// of column (0, 0) at time step 0, read here (two levels).
// \error as SlabReader::read_vertical_geometry; kInvalidInput when column (0, 0) has two
// equal levels.
std::optional<format::GridGeometry> plan_geometry(const ingest::InputCatalog& catalog,
                                                  const ingest::ScanOptions& scan,
                                                  const format::CodecSpec& codec);

}  // namespace strielad::build
