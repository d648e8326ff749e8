// SPDX-License-Identifier: Apache-2.0
// What a peer extraction returns: the paper's VTK clip pipeline, vtkFlyingEdges3D and
// OpenVDB's volumeToMesh, run on one node's samples so that tests and strielad-bench can
// compare them with this project's kernel on the same bricks. Free of VTK and OpenVDB
// types.
#pragma once

#include <cstdint>
#include <limits>

#include "extract/mesh.h"

namespace strielad::peers {

struct PeerResult {
  // Positions in the node's axis coordinates (NodeSamples::coords), whatever the peer
  // computed in (index space for vtkFlyingEdges3D and OpenVDB).
  Mesh mesh;
  // Wall seconds of the peer's own part only: building its data set from the samples
  // and running its filters, not the conversion to `mesh` nor the measures below.
  double seconds = 0;
  // Cells of the node's sample lattice the peer processed: (nx-1)(ny-1)(nz-1).
  std::uint64_t cells = 0;

  // Signed enclosed volume by the divergence theorem over `mesh`
  // (extract/mesh_metrics.h's enclosed_volume), in the product of the three axis units. Positive when the mesh is outward-oriented.
  // Only an enclosed volume when `closed`.
  double divergence_volume = 0;
  // vtkMassProperties::GetVolume() of the same surface (paper pipeline only; NaN for the
  // other peers).
  double mass_properties_volume = std::numeric_limits<double>::quiet_NaN();
  // Edges used by one triangle only, and edges used by more than two (vtkFeatureEdges
  // for the paper pipeline, peer_mesh.h's count_open_edges() for the others).
  std::uint64_t boundary_edges = 0;
  std::uint64_t non_manifold_edges = 0;
  // boundary_edges == 0 && non_manifold_edges == 0 (false for an empty mesh).
  bool closed = false;
};

}  // namespace strielad::peers
