// SPDX-License-Identifier: Apache-2.0
// The last step of extract_node_mesh (node_extractor.h): the kernel's mesh, built in
// lattice coordinates (NodeMeshScratch::builder), as the node's Mesh in axis
// coordinates, once per vertex: positions (exact on samples, interpolated inside cells),
// unit normals as covectors (a condition's gradient, or a box or node side's fixed
// normal; area-weighted face normals where a gradient is zero or undefined), attributes
// by trilinear interpolation, and each triangle's face kind.
#pragma once

#include <cstdint>
#include <vector>

#include "extract/conditions.h"
#include "extract/mesh.h"
#include "extract/node_mesh_scratch.h"
#include "extract/node_samples.h"

namespace strielad {

// Fills `mesh` (positions, normals, triangles, face kinds, attributes of
// `attribute_fields`) from scratch.builder; `set` the node's conditions (groups 0..n-1,
// node sides n..n+5). `clipped`: the general clipper made some of the vertices.
// `axis_normals` false: every normal +z (ExtractRequest::axis_normals). Returns
// whether a point strictly inside a cell rounded onto one of the cell's samples in axis
// coordinates (then two lattice-distinct vertices may share a position).
bool lattice_mesh_to_axis(const NodeSamples& samples, const ConditionSet& set,
                          const std::vector<std::uint32_t>& attribute_fields, bool clipped,
                          bool axis_normals, NodeMeshScratch& scratch, Mesh& mesh);

}  // namespace strielad
