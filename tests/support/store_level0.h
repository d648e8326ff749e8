// SPDX-License-Identifier: Apache-2.0
// Level 0 of a store's (step, variable) reassembled from its bricks, for tests that
// compare a conversion with its input.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "store/store.h"

namespace strielad::testing {

// Level 0 of (step, variable), x fastest. Neighbouring bricks share boundary samples;
// each shared sample must be the same in both (checked with EXPECT).
inline std::vector<double> assemble_level0(const Store& store, std::uint32_t step,
                                           std::uint32_t var) {
  constexpr double kUnset = -12345.0;
  const OctreeLayout& layout = store.octree();
  const Dims3 g = layout.grid();
  std::vector<double> out(g.count(), kUnset);
  for (NodeId n = 0; n < layout.level(0).node_count(); ++n) {
    const Brick b = store.read_brick(step, var, n);
    for (std::size_t z = 0; z < b.dims[2]; ++z)
      for (std::size_t y = 0; y < b.dims[1]; ++y)
        for (std::size_t x = 0; x < b.dims[0]; ++x) {
          const std::size_t gi = ((b.box.lo[2] + z) * g.y + b.box.lo[1] + y) * g.x + b.box.lo[0] + x;
          const double v = b.sample((z * b.dims[1] + y) * b.dims[0] + x);
          const double prev = out[gi];
          if (prev != kUnset) {
            EXPECT_TRUE((std::isnan(prev) && std::isnan(v)) || prev == v)
                << "node " << n << " disagrees with a neighbour at sample " << gi;
          }
          out[gi] = v;
        }
  }
  return out;
}

}  // namespace strielad::testing
