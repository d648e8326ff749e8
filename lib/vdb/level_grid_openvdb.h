// SPDX-License-Identifier: Apache-2.0
// The OpenVDB grid of a store level, for code that runs OpenVDB tools on it. Including
// this header costs ~25 s of compile time: keep it to few translation units.
#pragma once

#include <openvdb/openvdb.h>

#include "vdb/level_grid.h"

namespace strielad::vdb {

openvdb::FloatGrid::Ptr build_level_grid(const Store& store, std::uint32_t step,
                                         std::uint32_t variable, std::uint32_t level,
                                         const LevelGridOptions& options = {},
                                         LevelGridSummary* summary = nullptr);

}  // namespace strielad::vdb
