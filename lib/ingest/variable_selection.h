// SPDX-License-Identifier: Apache-2.0
// Which variables a conversion takes: the ones asked for, or by default every 3D
// (time?, vertical, lat, lon) variable on the grid of the first one found, the others
// skipped with a log line.
#pragma once

#include <string>
#include <vector>

#include "ingest/file_scan.h"

namespace strielad::ingest {

// Store names of the selected variables, in catalog order. By default the variables named
// in `geometry_sources` (the height fields that place terrain-following levels:
// vertical_geometry_detection.h) are left out: they place the grid, they are not data
// (asked for by name, they are converted too). Requested names may carry a
// leading '/'. Throws kNotFound for a requested variable that no file has (listing the
// available ones), kInvalidArgument for a name requested twice, and, when nothing is
// selectable by default, the most telling problem found (unstructured grid, missing
// coordinate variable...) or kNotFound. Whether every occurrence of a selected variable
// is usable and on the common grid is checked when the catalog is merged.
std::vector<std::string> select_variables(const std::vector<ScannedFile>& files,
                                          const std::vector<std::string>& requested,
                                          const std::vector<std::string>& geometry_sources = {});

}  // namespace strielad::ingest
