// SPDX-License-Identifier: Apache-2.0
// Extraction of one sub-volume inside one octree node as a closed, outward-oriented
// triangle mesh (formats/scene.md, "Extraction").
//
// Method: a cell crossed by one condition (nearly every cut cell) takes that
// condition's surface from a table of closed loops through the exact crossings of the
// trilinear field on its edges, each loop a fan of triangles (marching-cubes-like). A
// cell crossed by several conditions is split into six tetrahedra along its main
// diagonal (Kuhn); every condition of the sub-volume (ExtractRequest -> conditions.h) is
// linear inside a tetrahedron, so the region inside it is a convex polytope
// (TetClipper). Where such a cell, or the node's boundary, meets a cell crossed by one
// condition, the shared side is split along its diagonal so the loop there passes
// through the diagonal's crossing as the tetrahedra do (node faces are always split,
// so neighbouring nodes meet whatever crosses their cells). The mesh is the union of
// the faces on a condition's surface (limit and domain-box surfaces) or on the node's
// boundary. Cells wholly inside or outside are classified by bit masks and cost a few
// instructions, and vertices on lattice corners and edges are found by lattice element,
// not by hashing positions.
// Crossings within 2^-30 of a cell from a sample are the sample (tet_clipper.h), and
// triangles that still collapse once in axis coordinates are removed at the end
// (collapsed_triangles.h), so extreme value ratios leave no slivers or cracks.
//
// Parts: conditions.h (the conditions and their masks), cell_sweep.h (the walk over the
// cells), cell_kernel.h (each cut cell's faces), cell_tables.h (the marching tables),
// lattice_to_axis.h (positions, normals and attributes in axis coordinates).
#pragma once

#include "extract/extract_request.h"
#include "extract/mesh.h"
#include "extract/node_mesh_scratch.h"
#include "extract/node_samples.h"
#include "extract/thread_scratch.h"

namespace strielad {

// The sub-volume's mesh in the node, working in `scratch` (its buffers kept for the next
// call: a node costs no fresh pages).
Mesh extract_node_mesh(const NodeSamples& samples, const ExtractRequest& request, NodeMeshScratch& scratch,
                       ExtractStats* stats = nullptr);

// The same in this thread's scratch (this_thread_scratch()).
Mesh extract_node_mesh(const NodeSamples& samples, const ExtractRequest& request,
                       ExtractStats* stats = nullptr);

}  // namespace strielad
