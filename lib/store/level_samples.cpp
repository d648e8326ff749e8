// SPDX-License-Identifier: Apache-2.0
#include "store/level_samples.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <type_traits>

#include "core/error.h"

namespace strielad {
namespace {

// Bricks read ahead of `place` at once: enough to keep every core decompressing, few
// enough that a batch of large bricks stays small next to the level itself.
constexpr std::size_t kBatchBricks = 64;

template <typename T>
bool same_bits(T a, T b) {
  using Bits = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;
  return (std::isnan(a) && std::isnan(b)) || std::bit_cast<Bits>(a) == std::bit_cast<Bits>(b);
}

}  // namespace

LevelBrickCounts for_each_level_brick(const Store& store, std::uint32_t step,
                                      std::uint32_t variable, std::uint32_t level,
                                      const std::function<void(const Brick&)>& place,
                                      const BrickWanted& wanted) {
  const OctreeLayout& layout = store.octree();
  if (level >= layout.level_count()) {
    throw make_error(ErrorCode::kNotFound, "{}: level {} does not exist (the octree has {} levels)",
                     store.path().string(), level, layout.level_count());
  }
  const LevelShape& shape = layout.level(level);
  LevelBrickCounts counts;
  std::vector<NodeId> batch;
  std::vector<Brick> bricks;
  const auto flush = [&] {
    bricks.assign(batch.size(), Brick{});
    tbb::parallel_for(std::size_t{0}, batch.size(), [&](std::size_t i) {
      bricks[i] = store.read_brick(step, variable, batch[i]);
    });
    for (const Brick& b : bricks) {
      ++counts.bricks_read;
      counts.sample_bytes += b.bytes.size();
      place(b);
    }
    batch.clear();
  };
  for (NodeId n = shape.first_node; n < shape.first_node + shape.node_count(); ++n) {
    if (wanted && !wanted(store.node_entry(step, variable, n))) {
      ++counts.bricks_skipped;
      continue;
    }
    batch.push_back(n);
    if (batch.size() == kBatchBricks) flush();
  }
  if (!batch.empty()) flush();
  return counts;
}

template <typename T>
LevelSamples<T> read_level_samples(const Store& store, std::uint32_t step, std::uint32_t variable,
                                   std::uint32_t level, const BrickWanted& wanted) {
  LevelSamples<T> out;
  if (level < store.octree().level_count()) out.dims = store.octree().level(level).samples;
  const auto& n = out.dims;
  out.values.assign(n[0] * n[1] * n[2], std::numeric_limits<T>::quiet_NaN());
  std::vector<std::uint8_t> written(out.values.size(), 0);
  out.counts = for_each_level_brick(store, step, variable, level, [&](const Brick& brick) {
    const std::vector<T> values = brick.to_vector<T>();
    const IndexBox& box = brick.box;
    std::size_t i = 0;
    for (std::size_t z = 0; z < brick.dims[2]; ++z) {
      for (std::size_t y = 0; y < brick.dims[1]; ++y) {
        const std::size_t row = ((box.lo[2] + z) * n[1] + box.lo[1] + y) * n[0] + box.lo[0];
        for (std::size_t x = 0; x < brick.dims[0]; ++x, ++i) {
          const std::size_t at = row + x;
          if (written[at] && !same_bits(out.values[at], values[i])) ++out.shared_mismatches;
          out.values[at] = values[i];
          written[at] = 1;
        }
      }
    }
  }, wanted);
  return out;
}

template LevelSamples<float> read_level_samples<float>(const Store&, std::uint32_t, std::uint32_t,
                                                       std::uint32_t, const BrickWanted&);
template LevelSamples<double> read_level_samples<double>(const Store&, std::uint32_t,
                                                         std::uint32_t, std::uint32_t,
                                                         const BrickWanted&);

}  // namespace strielad
