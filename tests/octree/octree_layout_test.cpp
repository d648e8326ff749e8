// SPDX-License-Identifier: Apache-2.0
#include "octree/octree_layout.h"

#include <gtest/gtest.h>

#include <set>

#include "core/error.h"

namespace strielad {
namespace {

TEST(OctreeLayoutTest, PaperGridWithBrick20Has51393Nodes) {
  const OctreeLayout layout(Dims3{1429, 1556, 150}, 20);
  EXPECT_EQ(layout.node_count(), 51393u);
  EXPECT_EQ(layout.level(0).node_count(), 72u * 78u * 8u);  // 44,928 leaves
  EXPECT_EQ(layout.level_count(), 8u);
  EXPECT_EQ(layout.level(layout.level_count() - 1).node_count(), 1u);
  // The paper: inner nodes add about 15 % to the data.
  EXPECT_GT(layout.overhead_fraction(), 0.12);
  EXPECT_LT(layout.overhead_fraction(), 0.16);
}

TEST(OctreeLayoutTest, AxisStopsHalvingOnceOneNodeSpansIt) {
  const OctreeLayout layout(Dims3{1429, 1556, 150}, 20);
  // z has 8 leaves: halved three times (8, 4, 2, 1) and then kept.
  EXPECT_EQ(layout.level(3).nodes[2], 1u);
  EXPECT_EQ(layout.level(3).stride[2], 8u);
  EXPECT_EQ(layout.level(7).stride[2], 8u);
  EXPECT_EQ(layout.level(7).stride[0], 128u);
}

TEST(OctreeLayoutTest, EveryLevelCoversTheWholeDomain) {
  const OctreeLayout layout(Dims3{101, 37, 9}, 8);
  for (std::size_t l = 0; l < layout.level_count(); ++l) {
    const LevelShape& s = layout.level(l);
    EXPECT_EQ(layout.fine_index(l, 0, s.samples[0] - 1), 100u) << "level " << l;
    EXPECT_EQ(layout.fine_index(l, 1, s.samples[1] - 1), 36u) << "level " << l;
    EXPECT_EQ(layout.fine_index(l, 2, s.samples[2] - 1), 8u) << "level " << l;
  }
}

TEST(OctreeLayoutTest, OwnedBoxesOfALevelPartitionTheGrid) {
  const OctreeLayout layout(Dims3{45, 30, 17}, 6);
  for (std::size_t l = 0; l < layout.level_count(); ++l) {
    const LevelShape& s = layout.level(l);
    std::size_t total = 0;
    for (NodeId n = s.first_node; n < s.first_node + s.node_count(); ++n) {
      total += layout.owned_fine_box(layout.key(n)).count();
    }
    EXPECT_EQ(total, 45u * 30u * 17u) << "level " << l;
  }
}

TEST(OctreeLayoutTest, ChildrenCoverTheirParentExactly) {
  const OctreeLayout layout(Dims3{45, 30, 17}, 6);
  for (NodeId n = 0; n < layout.node_count(); ++n) {
    const auto kids = layout.children(n);
    if (kids.empty()) continue;
    std::size_t owned = 0;
    IndexBox hull = layout.fine_box(layout.key(kids.front()));
    for (NodeId c : kids) {
      ASSERT_EQ(layout.parent(c), n);
      owned += layout.owned_fine_box(layout.key(c)).count();
      const IndexBox b = layout.fine_box(layout.key(c));
      for (int a = 0; a < 3; ++a) {
        hull.lo[a] = std::min(hull.lo[a], b.lo[a]);
        hull.hi[a] = std::max(hull.hi[a], b.hi[a]);
      }
    }
    EXPECT_EQ(owned, layout.owned_fine_box(layout.key(n)).count()) << "node " << n;
    EXPECT_EQ(hull, layout.fine_box(layout.key(n))) << "node " << n;
  }
}

TEST(OctreeLayoutTest, NodeIdAndKeyRoundTrip) {
  const OctreeLayout layout(Dims3{64, 64, 64}, 16);
  std::set<NodeId> seen;
  for (NodeId n = 0; n < layout.node_count(); ++n) {
    EXPECT_EQ(layout.id(layout.key(n)), n);
    seen.insert(n);
  }
  EXPECT_EQ(layout.node_count(), 64u + 8u + 1u);
  EXPECT_FALSE(layout.parent(layout.root()).has_value());
  EXPECT_THROW(layout.key(static_cast<NodeId>(layout.node_count())), Error);
}

TEST(OctreeLayoutTest, BricksShareBoundarySamples) {
  const OctreeLayout layout(Dims3{41, 21, 21}, 20);
  const IndexBox a = layout.level_box(NodeKey{0, {0, 0, 0}});
  const IndexBox b = layout.level_box(NodeKey{0, {1, 0, 0}});
  EXPECT_EQ(a.hi[0], 20u);
  EXPECT_EQ(b.lo[0], 20u);
  EXPECT_EQ(a.extent(0), 21u);
}

TEST(OctreeLayoutTest, OneSampleThickGridHasOneLevelOfFlatBricks) {
  const OctreeLayout layout(Dims3{30, 30, 1}, 10);
  EXPECT_EQ(layout.level(0).nodes[2], 1u);
  EXPECT_EQ(layout.level_box(NodeKey{0, {0, 0, 0}}).extent(2), 1u);
}

TEST(OctreeLayoutTest, RejectsZeroDimensionsAndTinyBricks) {
  EXPECT_THROW(OctreeLayout(Dims3{0, 5, 5}, 8), Error);
  EXPECT_THROW(OctreeLayout(Dims3{5, 5, 5}, 1), Error);
}

TEST(OctreeLayoutTest, RejectsGridsNeedingMoreThan32BitNodeIds) {
  try {
    OctreeLayout(Dims3{std::size_t{1} << 30, std::size_t{1} << 30, 1000}, 2);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kInvalidArgument);
    EXPECT_NE(std::string(e.what()).find("2^32"), std::string::npos);
  }
}

}  // namespace
}  // namespace strielad
