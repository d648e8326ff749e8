// SPDX-License-Identifier: Apache-2.0
// OpenVDB's volumeToMesh on one node's samples: a peer of this project's kernel for
// tests and strielad-bench. OpenVDB types stay inside the .cpp (~40 s to
// compile: OpenVDB core plus the volumeToMesh templates).
//
// The field is copied into a FloatGrid in index space (voxel (i, j, k) = sample (i, j, k),
// via tools::copyFromDense, with one extra layer on every side repeating the outermost
// samples so that the grid's background never meets the samples), meshed at the iso
// value without adaptivity, and every point is mapped to the real axes piecewise
// linearly (peers/peer_mesh.h). The grid is classed as a level set, so volumeToMesh
// treats values below iso as inside and orients polygons outward, towards larger
// values: the same convention as run_flying_edges. volumeToMesh is a dual method (one
// vertex per intersected cell, inside the cell); polygons with a vertex in the padding
// cells are dropped, so the surface is open, half a cell short of the node's boundary
// (vtkFlyingEdges3D's reaches it). Normals are area-weighted face normals.
// NaN samples become the grid background, a value far below iso (missing counts as "no
// cloud"); ±Inf are clamped to ±1e37.
#pragma once

#include <cstddef>

#include "extract/node_samples.h"
#include "peers/peer_result.h"

namespace strielad::peers {

struct VolumeToMeshOptions {
  // 1: OpenVDB runs in a one-thread oneTBB arena (per-core figures); 0: the caller's
  // arena; n: n threads.
  unsigned threads = 1;
  // volumeToMesh's adaptivity in [0, 1]; 0 = uniform (what the comparisons use).
  double adaptivity = 0.0;
};

// \error kInvalidArgument if the samples are malformed, `field` is out of range, iso is
//        not finite or adaptivity is outside [0, 1].
PeerResult run_openvdb_volume_to_mesh(const NodeSamples& samples, std::size_t field, double iso,
                                      const VolumeToMeshOptions& options = {});

}  // namespace strielad::peers
