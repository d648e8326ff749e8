// SPDX-License-Identifier: Apache-2.0
// Octree size arithmetic near and beyond 2^31 cells, on the layout alone (no data): node
// counts, ids and keys of the last nodes, boxes at the far end of the grid, owned boxes
// that partition the grid exactly in 64-bit counts, and clear errors past the limits.
#include <gtest/gtest.h>

#include <cstdint>

#include "octree/octree_layout.h"
#include "support/expect_error.h"

namespace strielad {
namespace {

using testing::expect_error;

// Sum of owned samples over all nodes of one level, per axis (owned boxes are products
// of per-axis intervals), so that millions of nodes cost a few thousand calls.
std::uint64_t owned_samples(const OctreeLayout& layout, std::uint32_t level) {
  const LevelShape& s = layout.level(level);
  std::uint64_t product = 1;
  for (int a = 0; a < 3; ++a) {
    std::uint64_t sum = 0;
    for (std::uint32_t i = 0; i < s.nodes[a]; ++i) {
      NodeKey key{level, {0, 0, 0}};
      key.index[a] = i;
      sum += layout.owned_fine_box(key).extent(a);
    }
    product *= sum;
  }
  return product;
}

void expect_consistent(const OctreeLayout& layout) {
  const Dims3 g = layout.grid();
  const std::uint64_t cells = std::uint64_t{g.x} * g.y * g.z;
  std::uint64_t nodes = 0;
  for (std::uint32_t l = 0; l < layout.level_count(); ++l) {
    const LevelShape& s = layout.level(l);
    EXPECT_EQ(owned_samples(layout, l), cells) << "level " << l;
    EXPECT_EQ(s.first_node, nodes) << "level " << l;
    nodes += s.node_count();
    // The level's last node: id and key agree, its box ends at the grid's far corner.
    const NodeId last = static_cast<NodeId>(s.first_node + s.node_count() - 1);
    const NodeKey key = layout.key(last);
    EXPECT_EQ(layout.id(key), last);
    const IndexBox fine = layout.fine_box(key);
    EXPECT_EQ(fine.hi[0], g.x - 1);
    EXPECT_EQ(fine.hi[1], g.y - 1);
    EXPECT_EQ(fine.hi[2], g.z - 1);
  }
  EXPECT_EQ(nodes, layout.node_count());
  EXPECT_EQ(layout.root(), layout.node_count() - 1);
  EXPECT_TRUE(layout.children(layout.root()).size() >= 1 || layout.level_count() == 1);
}

TEST(HugeGridLayoutTest, TwoTo31Cells) {
  const OctreeLayout layout(Dims3{2048, 2048, 512}, 24);
  EXPECT_EQ(layout.level(0).nodes, (std::array<std::size_t, 3>{86, 86, 22}));
  expect_consistent(layout);
}

TEST(HugeGridLayoutTest, TwoTo32CellsOnOneLevel) {
  const OctreeLayout layout(Dims3{65536, 65536, 1}, 24);
  EXPECT_EQ(layout.level(0).node_count(), 2731u * 2731u);
  EXPECT_EQ(layout.level(0).nodes[2], 1u);
  expect_consistent(layout);
}

TEST(HugeGridLayoutTest, LongestAxisAllowed) {
  // 2^31 samples along x: 89.5 million leaves, node ids still fit 32 bits.
  const std::size_t n = std::size_t{1} << 31;
  const OctreeLayout layout(Dims3{n, 2, 2}, 24);
  EXPECT_EQ(layout.level(0).nodes[0], (n - 1 + 23) / 24);
  EXPECT_GT(layout.node_count(), 178'000'000u);
  const NodeKey last = layout.key(static_cast<NodeId>(layout.level(0).node_count() - 1));
  EXPECT_EQ(layout.fine_box(last).hi[0], n - 1);
  EXPECT_EQ(layout.owned_fine_box(last).count(), (n - 1 - std::size_t{last.index[0]} * 24 + 1) * 4);
  // Per-axis partition on the coarsest levels (a few thousand nodes).
  for (std::uint32_t l = 20; l < layout.level_count(); ++l) {
    EXPECT_EQ(owned_samples(layout, l), std::uint64_t{n} * 4) << "level " << l;
  }
  EXPECT_EQ(layout.fine_box(layout.key(layout.root())).hi[0], n - 1);
}

TEST(HugeGridLayoutTest, SmallBricksOnAHugeGrid) {
  const OctreeLayout layout(Dims3{2048, 2048, 512}, 2);
  EXPECT_EQ(layout.level(0).node_count(), 1024u * 1024u * 256u);
  expect_consistent(layout);
}

TEST(HugeGridLayoutTest, BeyondTheLimitsIsAClearError) {
  expect_error([] { OctreeLayout(Dims3{(std::size_t{1} << 31) + 1, 2, 2}, 24); },
               ErrorCode::kInvalidArgument, {"larger than 2^31 samples"});
  expect_error([] { OctreeLayout(Dims3{131072, 131072, 2}, 2); }, ErrorCode::kInvalidArgument,
               {"131072x131072x2", "brick 2", "more than 2^32 octree nodes"});
}

}  // namespace
}  // namespace strielad
