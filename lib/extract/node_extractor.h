// SPDX-License-Identifier: Apache-2.0
// Extraction of one sub-volume inside one octree node as a closed, outward-oriented
// triangle mesh (formats/scene.md, "Extraction").
//
// Method: each lattice cell is split into six tetrahedra along its main diagonal
// (Kuhn), so neighbouring cells split shared faces the same way. Every condition of
// the sub-volume (ExtractRequest -> conditions.h) is linear inside a tetrahedron, so
// the region inside it is a convex polytope (TetClipper). The mesh is the union of
// the polytope faces that lie on a condition's zero plane (limit and domain-box
// surfaces) or on the node's boundary. The limit surfaces pass through the exact
// crossings of the trilinear field on every lattice edge, like the paper's clip
// pipeline. Cells wholly inside or outside are classified by bit masks and cost a few
// instructions; a cell crossed by one condition takes its tetrahedra's polygons from a
// table, and vertices on lattice corners and edges are found by lattice element, not
// by hashing positions. The same triangles as clipping every tetrahedron one by one.
// Crossings within 2^-30 of a cell from a sample are the sample (tet_clipper.h), and
// triangles that still collapse once in axis coordinates are removed at the end
// (collapsed_triangles.h), so extreme value ratios leave no slivers or cracks.
//
// Scratch buffers (condition masks, vertex slots, the mesh builder) are kept per
// thread between calls (about 1 MB per thread for 25^3 samples): concurrent calls from
// different threads are fine.
#pragma once

#include "extract/extract_request.h"
#include "extract/mesh.h"
#include "extract/node_samples.h"

namespace strielad {

Mesh extract_node_mesh(const NodeSamples& samples, const ExtractRequest& request,
                       ExtractStats* stats = nullptr);

}  // namespace strielad
