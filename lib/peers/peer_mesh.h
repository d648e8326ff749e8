// SPDX-License-Identifier: Apache-2.0
// Small mesh helpers the peers share (plain C++): open-edge counts by vertex index,
// area-weighted vertex normals, and the map from a lattice's index space to its real
// axes. Volume and area are extract/mesh_metrics.h's.
#pragma once

#include <cstdint>

#include "extract/mesh.h"
#include "extract/node_samples.h"

namespace strielad::peers {

struct EdgeCounts {
  std::uint64_t boundary = 0;      // edges used by exactly one triangle
  std::uint64_t non_manifold = 0;  // edges used by more than two triangles
  bool closed() const { return boundary == 0 && non_manifold == 0; }
};

// Counts edges by vertex index, as vtkFeatureEdges does (coincident vertices with
// different indices are not merged; extract/mesh_metrics.h's check_mesh merges them).
EdgeCounts count_open_edges(const Mesh& mesh);

// Replaces mesh.normals by area-weighted averages of the adjacent triangles' normals,
// normalised; a vertex whose triangles all have zero area gets (0, 0, 1).
void compute_vertex_normals(Mesh& mesh);

// Maps a fractional sample index along axis `axis` of `samples` to the axis coordinate:
// piecewise linear between samples (exact for points on lattice edges, which is where
// marching-cubes style vertices lie). Indices outside [0, n-1] extrapolate linearly
// from the first or last cell.
double index_to_axis(const NodeSamples& samples, int axis, double index);

// d(axis coordinate)/d(index) along `axis` at fractional index `index` (the spacing of
// the cell containing it); negative on a descending axis.
double axis_spacing_at(const NodeSamples& samples, int axis, double index);

// Maps an index-space mesh (positions in fractional sample indices, normals in index
// space) to axis coordinates in place: positions by index_to_axis, normals by the
// inverse transpose of the local spacing, renormalised; reverses the winding when an
// odd number of axes descend, so the orientation is kept.
void map_index_mesh_to_axes(Mesh& mesh, const NodeSamples& samples);

}  // namespace strielad::peers
