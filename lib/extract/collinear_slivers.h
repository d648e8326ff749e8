// SPDX-License-Identifier: Apache-2.0
// Where positions round onto samples in axis coordinates (collapsed_triangles.h), a
// triangle can also keep three distinct vertices that now lie on one line: zero area,
// though every edge still has its partner. Such a sliver goes by splitting the triangle
// across its long edge at the sliver's middle vertex: the neighbour (A, C, D) across
// the sliver's long edge C-A becomes (A, M, D) and (M, C, D), which meet the sliver's
// two short edges' neighbours, so a closed, consistently oriented mesh stays closed and
// consistently oriented, and no area or volume changes.
#pragma once

#include <cstddef>

#include "extract/mesh.h"

namespace strielad {

// Removes the slivers above (zero area: the cross product of a triangle's edges from
// its first vertex is exactly 0, as check_mesh computes it; three distinct positions),
// in rounds until none is left or a round makes no progress. A sliver whose long edge
// has no single opposite triangle, or whose neighbour there is a sliver too, waits for
// a later round or stays. Returns the number of slivers removed.
std::size_t split_collinear_slivers(Mesh& mesh);

}  // namespace strielad
