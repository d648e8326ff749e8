// SPDX-License-Identifier: Apache-2.0
#include "robust/level_samples.h"

#include <bit>
#include <cmath>
#include <limits>

namespace strielad::robust {

LevelSamples read_level_samples(const Store& store, std::uint32_t step, std::uint32_t variable,
                                std::size_t level) {
  const OctreeLayout& layout = store.octree();
  const LevelShape& shape = layout.level(level);
  LevelSamples out;
  out.dims = shape.samples;
  out.values.assign(shape.samples[0] * shape.samples[1] * shape.samples[2],
                    std::numeric_limits<double>::quiet_NaN());
  std::vector<std::uint8_t> written(out.values.size(), 0);
  for (NodeId n = shape.first_node; n < shape.first_node + shape.node_count(); ++n) {
    const Brick brick = store.read_brick(step, variable, n);
    std::size_t i = 0;
    for (std::size_t z = brick.box.lo[2]; z <= brick.box.hi[2]; ++z)
      for (std::size_t y = brick.box.lo[1]; y <= brick.box.hi[1]; ++y)
        for (std::size_t x = brick.box.lo[0]; x <= brick.box.hi[0]; ++x, ++i) {
          const std::size_t at = (z * shape.samples[1] + y) * shape.samples[0] + x;
          const double v = brick.sample(i);
          if (written[at]) {
            const double before = out.values[at];
            const bool same = (std::isnan(before) && std::isnan(v)) ||
                              std::bit_cast<std::uint64_t>(before) == std::bit_cast<std::uint64_t>(v);
            out.shared_mismatches += same ? 0 : 1;
          }
          out.values[at] = v;
          written[at] = 1;
        }
  }
  return out;
}

}  // namespace strielad::robust
