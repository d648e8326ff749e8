// SPDX-License-Identifier: Apache-2.0
// The sweep of extract_node_mesh over a node's cells (node_extractor.h): rows of cells
// skipped or taken whole by their sample rows' summaries, cells crossed by several
// conditions found first, then each cut cell through the kernel (cell_kernel.h), by the
// marching table or per tetrahedron.
#pragma once

#include <array>
#include <cstddef>

#include "extract/cell_kernel.h"
#include "extract/conditions.h"
#include "extract/extract_request.h"
#include "extract/node_mesh_scratch.h"

namespace strielad {

// Every cell of the node in `dims` through `kernel`, by the condition masks of `set`
// (narrow or wide); counts cells and tetrahedra in `stats`.
void sweep_cells(const ConditionSet& set, const std::array<std::size_t, 3>& dims,
                 NodeMeshScratch& scratch, CellKernel& kernel, ExtractStats& stats);

}  // namespace strielad
