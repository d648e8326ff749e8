// SPDX-License-Identifier: Apache-2.0
// The kernel keeps vertices apart on the sample lattice; in double axis coordinates some
// of them can still land on one point: a surface crossing an edge 1e-30 of a cell from a
// sample (1e-30 next to 1e30 in one cell), or a domain face 1e-14 of a cell from a sample
// plane, is at the sample itself once the position is c[i] + f (c[i+1] - c[i]). And where
// a limit has min = max the region is a sheet without volume, bounded by two coincident
// surfaces. This pass removes what that leaves behind, in position space:
// - triangles with two vertices at one position (zero area), and
// - pairs of triangles over the same three positions in opposite orientations (a slab or
//   sheet without volume),
// then the vertices no triangle uses. Both removals keep a closed, consistently oriented
// mesh closed and consistently oriented (docs/robustness.md, "Extraction").
#pragma once

#include <cstddef>

#include "extract/mesh.h"

namespace strielad {

// Removes the triangles above; `look_for_sheets` runs the opposite-pair search even when
// no zero-area triangle was found (a limit with min = max). Returns the number of
// triangles removed.
std::size_t remove_collapsed_triangles(Mesh& mesh, bool look_for_sheets);

}  // namespace strielad
