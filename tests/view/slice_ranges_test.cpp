// SPDX-License-Identifier: Apache-2.0
// The colour range of a slice without its own range (view/slice_ranges.h): the smallest
// and largest finite value among the slice vertices shown, per slice, over every node
// that shows a mesh; missing values ignored; a slice with no finite value has none.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "lod/lod_test_grids.h"
#include "view/node_geometry.h"
#include "view/slice_ranges.h"

namespace strielad::view {
namespace {

// One slice triangle over the store (lon 4.5..14.5, lat 54.5..47.5) whose three
// vertices carry `values`.
Mesh slice_triangle(std::array<float, 3> values) {
  Mesh m;
  m.positions = {{6.0, 50.0, 1000.0}, {8.0, 50.0, 1000.0}, {7.0, 52.0, 1000.0}};
  m.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  m.triangles = {{0, 1, 2}};
  m.face_kinds = {FaceKind::kSlice};
  m.attribute_names = {"ta"};
  m.attributes = {{values[0], values[1], values[2]}};
  return m;
}

SliceResult slice(std::array<float, 3> values) {
  SliceResult s;
  s.outcome = NodeOutcome::kMesh;
  s.mesh = slice_triangle(values);
  return s;
}

std::shared_ptr<const NodeGeometry> placed(NodeId node,
                                           std::vector<SliceResult> slices) {
  static const GeometryPlacer placer(lod::testing::geographic_manifest(11, 8, {0.0, 12000.0}));
  protocol::NodeResult result;
  result.node = node;
  result.slices = std::move(slices);
  return placer.place(result, 0, [](std::uint32_t) { return 0; });
}

TEST(ShownSliceRanges, SpanEveryShownNodePerSliceIgnoringMissingValues) {
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  ProgressiveMeshes meshes;
  lod::CutDiff diff;
  diff.added = {{1, 1.0f}, {2, 2.0f}, {3, 3.0f}};
  meshes.apply_cut_diff(diff);
  // Slice 0 spans 250..300 over nodes 1 and 2; slice 1 has only missing values; slice 2
  // only in node 2.
  ASSERT_TRUE(meshes.accept(1, placed(1, {slice({260, kNaN, 300}), slice({kNaN, kNaN, kNaN})})));
  ASSERT_TRUE(meshes.accept(2, placed(2, {slice({250, 255, kNaN}), SliceResult{},
                                          slice({-5, 7, 1})})));
  // Node 3 has not answered: it shows nothing and adds nothing.
  const auto ranges = shown_slice_ranges(meshes, 4);
  ASSERT_EQ(ranges.size(), 4u);
  ASSERT_TRUE(ranges[0].has_value());
  EXPECT_EQ((*ranges[0])[0], 250.0f);
  EXPECT_EQ((*ranges[0])[1], 300.0f);
  EXPECT_FALSE(ranges[1].has_value());
  ASSERT_TRUE(ranges[2].has_value());
  EXPECT_EQ((*ranges[2])[0], -5.0f);
  EXPECT_EQ((*ranges[2])[1], 7.0f);
  EXPECT_FALSE(ranges[3].has_value());
  // Asking for fewer slices than the meshes carry gives just those.
  EXPECT_EQ(shown_slice_ranges(meshes, 1).size(), 1u);
}

TEST(ShownSliceRanges, ANodeLeavingTheCutTakesItsValuesAlong) {
  ProgressiveMeshes meshes;
  lod::CutDiff diff;
  diff.added = {{1, 1.0f}, {2, 2.0f}};
  meshes.apply_cut_diff(diff);
  ASSERT_TRUE(meshes.accept(1, placed(1, {slice({1, 2, 3})})));
  ASSERT_TRUE(meshes.accept(2, placed(2, {slice({100, 200, 300})})));
  EXPECT_EQ((*shown_slice_ranges(meshes, 1)[0])[1], 300.0f);
  lod::CutDiff gone;
  gone.removed = {2};
  meshes.apply_cut_diff(gone);
  const auto ranges = shown_slice_ranges(meshes, 1);
  ASSERT_TRUE(ranges[0].has_value());
  EXPECT_EQ((*ranges[0])[0], 1.0f);
  EXPECT_EQ((*ranges[0])[1], 3.0f);
}

}  // namespace
}  // namespace strielad::view
