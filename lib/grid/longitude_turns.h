// SPDX-License-Identifier: Apache-2.0
// Longitude ranges mean the same region whatever the grid's convention (0..360,
// -180..180, or unwrapped like 170..190): a range [lo, hi] narrower than a full turn
// meets a node whose longitudes span [a, b] at every whole turn k with
// [lo - 360 k, hi - 360 k] overlapping [a, b]. The node's part of the range is that
// interval in its own longitudes, and its meshes are output 360 k degrees on, so that a
// range keeps its own convention (-30..30 on a grid stored 0..360 comes out -30..30) and
// regions across a periodic grid's seam are continuous (formats/scene.md, "Longitude
// ranges").
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace strielad {

inline constexpr double kFullTurn = 360.0;

// The turns k, ascending; empty when the range misses the node (touching counts as
// meeting, as for every domain range). `lo <= hi`, `hi - lo < 360`, all finite.
inline std::vector<int> longitude_turns(double lo, double hi, double a, double b) {
  const double node_lo = std::min(a, b), node_hi = std::max(a, b);
  // [lo - 360 k, hi - 360 k] meets [node_lo, node_hi]: lo - 360 k <= node_hi and
  // hi - 360 k >= node_lo.
  const double first = std::ceil((lo - node_hi) / kFullTurn);
  const double last = std::floor((hi - node_lo) / kFullTurn);
  std::vector<int> turns;
  for (double k = first - 1; k <= last + 1; k += 1.0) {
    // The divisions above round; the test is exact.
    if (lo - kFullTurn * k <= node_hi && hi - kFullTurn * k >= node_lo) {
      turns.push_back(static_cast<int>(k));
    }
  }
  return turns;
}

}  // namespace strielad
