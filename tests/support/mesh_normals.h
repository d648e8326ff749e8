// SPDX-License-Identifier: Apache-2.0
// Checks of extracted meshes' normals for the tests.
#pragma once

#include <array>
#include <cstddef>

#include "extract/mesh.h"

namespace strielad::testing {

// How many vertices have a normal pointing away from the vertices' centroid: all of
// them on an outward-oriented convex blob.
inline std::size_t normals_away_from_centroid(const Mesh& mesh) {
  std::array<double, 3> centre{0, 0, 0};
  for (const auto& p : mesh.positions) {
    for (int a = 0; a < 3; ++a) centre[a] += p[a] / static_cast<double>(mesh.positions.size());
  }
  std::size_t outward = 0;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    double d = 0;
    for (int a = 0; a < 3; ++a) d += (mesh.positions[i][a] - centre[a]) * mesh.normals[i][a];
    outward += d > 0;
  }
  return outward;
}

}  // namespace strielad::testing
