// SPDX-License-Identifier: Apache-2.0
// The manifest's grid geometry (formats/store.md, "Grid geometry (version 5)") for what
// the inputs hold: terrain-following levels as a per-sample height or pressure field, and
// the model's surface height.
#pragma once

#include <optional>

#include "format/manifest.h"
#include "ingest/input_catalog.h"

namespace strielad::build {

// None when the catalog has neither a vertical geometry nor a surface. The field is stored
// as float32 with `codec`'s Blosc settings and the lorenzo3 predictor (heights and
// pressures are smooth); its orientation comes from the horizontal axes and the direction
// of column (0, 0) at time step 0, read here (two levels).
// \error as SlabReader::read_vertical_geometry; kInvalidInput when column (0, 0) has two
// equal levels.
std::optional<format::GridGeometry> plan_geometry(const ingest::InputCatalog& catalog,
                                                  const ingest::ScanOptions& scan,
                                                  const format::CodecSpec& codec);

}  // namespace strielad::build
