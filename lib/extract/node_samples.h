// SPDX-License-Identifier: Apache-2.0
// The input of one node's extraction: the node's sample lattice on the dataset's real
// axes and the values of the fields it needs (decoded bricks).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace strielad {

struct NodeSamples {
  // Sample coordinates along x, y, z in axis units (strictly monotonic, ascending or
  // descending; non-uniform allowed). dims[a] == coords[a].size() >= 2.
  std::array<std::vector<double>, 3> coords;
  // fields[f] holds dims[0]*dims[1]*dims[2] values, x fastest; NaN = missing (fill).
  std::vector<std::vector<float>> fields;
  // Node sides (x lo, x hi, y lo, y hi, z lo, z hi) that are the edge of the dataset's
  // grid: their faces are FaceKind::kGridBoundary, not shared with a neighbour.
  std::array<bool, 6> grid_edge{};

  std::array<std::size_t, 3> dims() const {
    return {coords[0].size(), coords[1].size(), coords[2].size()};
  }
  std::size_t sample_count() const {
    return coords[0].size() * coords[1].size() * coords[2].size();
  }
};

}  // namespace strielad
