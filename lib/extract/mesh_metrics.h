// SPDX-License-Identifier: Apache-2.0
// Measures of a triangle mesh used by tests, the benchmarks and `--json` output:
// enclosed volume, closedness and orientation, degenerate elements.
#pragma once

#include <array>
#include <cstdint>

#include "core/vec3.h"
#include "extract/mesh.h"

namespace strielad {

struct MeshCheck {
  std::uint64_t vertices = 0;          // distinct positions
  std::uint64_t edges = 0;             // undirected edges between distinct positions
  std::uint64_t open_edges = 0;        // used by one triangle
  std::uint64_t nonmanifold_edges = 0; // used by more than two triangles
  std::uint64_t misoriented_edges = 0; // used twice in the same direction
  std::uint64_t degenerate_triangles = 0;  // zero area
  std::uint64_t bad_normals = 0;       // NaN, infinite or not unit length
  std::uint64_t bad_positions = 0;     // NaN or infinite
  bool closed() const {
    return open_edges == 0 && nonmanifold_edges == 0 && misoriented_edges == 0;
  }
  bool clean() const {
    return closed() && degenerate_triangles == 0 && bad_normals == 0 && bad_positions == 0;
  }
};

// Whether triangle a, b, c has zero area as check_mesh counts it: the cross product of
// its edges from a is exactly 0 in double (coincident or collinear points).
bool zero_area(const std::array<double, 3>& a, const std::array<double, 3>& b,
               const std::array<double, 3>& c);

// Triangle t's normal scaled by twice its area (the cross product of its edges from its
// first vertex): outward for a counter-clockwise triangle.
inline Vec3 area_normal(const Mesh& mesh, const std::array<std::uint32_t, 3>& t) {
  const auto& p0 = mesh.positions[t[0]];
  return cross(sub(mesh.positions[t[1]], p0), sub(mesh.positions[t[2]], p0));
}

// Vertices are identified by exact position (a mesh may duplicate a position with
// different normals where surfaces meet at a crease).
MeshCheck check_mesh(const Mesh& mesh);

// Signed volume enclosed by the triangles (divergence theorem, in double), positive for
// an outward-oriented closed mesh; in the units of the positions.
double enclosed_volume(const Mesh& mesh);

double surface_area(const Mesh& mesh);

}  // namespace strielad
