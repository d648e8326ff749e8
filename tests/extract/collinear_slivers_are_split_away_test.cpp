// SPDX-License-Identifier: Apache-2.0
// split_collinear_slivers removes zero-area triangles whose three distinct vertices lie
// on one line by splitting the neighbour across the long edge at the middle vertex: the
// mesh stays closed and oriented, its volume does not change, and every other triangle
// is left alone.
#include <gtest/gtest.h>

#include "extract/collinear_slivers.h"
#include "extract/mesh_metrics.h"

namespace strielad {
namespace {

// The unit cube's 12 triangles, outward (vertex i at (i & 1, i >> 1 & 1, i >> 2 & 1)).
Mesh unit_cube() {
  Mesh m;
  for (int i = 0; i < 8; ++i) {
    m.positions.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
    m.normals.push_back({0, 0, 1});
  }
  m.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  m.face_kinds.assign(m.triangles.size(), FaceKind::kNodeBoundary);
  return m;
}

// The cube with the top face's triangle (4, 5, 7) replaced by two through a point M on
// the diagonal 4-7 (a position of its own), and the sliver (4, M, 7) that closes the
// gap on the other side of that diagonal: closed, one zero-area triangle.
Mesh cube_with_sliver(const std::array<double, 3>& m_position) {
  Mesh m = unit_cube();
  const auto mid = static_cast<std::uint32_t>(m.positions.size());
  m.positions.push_back(m_position);
  m.normals.push_back({0, 0, 1});
  m.triangles[2] = {4, 5, mid};
  m.triangles.push_back({mid, 5, 7});
  m.triangles.push_back({4, mid, 7});  // the sliver
  m.face_kinds.resize(m.triangles.size(), FaceKind::kLimit);
  return m;
}

TEST(CollinearSlivers, SliverGoesAndTheMeshStaysClosed) {
  Mesh m = cube_with_sliver({0.25, 0.25, 1.0});
  const MeshCheck before = check_mesh(m);
  ASSERT_TRUE(before.closed());
  ASSERT_EQ(before.degenerate_triangles, 1u);
  EXPECT_EQ(split_collinear_slivers(m), 1u);
  const MeshCheck after = check_mesh(m);
  EXPECT_TRUE(after.closed());
  EXPECT_EQ(after.nonmanifold_edges, 0u);
  EXPECT_EQ(after.degenerate_triangles, 0u);
  EXPECT_EQ(m.triangles.size(), 14u);  // 12 + 2 - the sliver + one from the split
  EXPECT_EQ(m.face_kinds.size(), m.triangles.size());
  EXPECT_DOUBLE_EQ(enclosed_volume(m), 1.0);
}

TEST(CollinearSlivers, MeshesWithoutSliversAreUntouched) {
  Mesh m = unit_cube();
  const Mesh before = m;
  EXPECT_EQ(split_collinear_slivers(m), 0u);
  EXPECT_EQ(m, before);
  // A zero-area triangle with two vertices at one position is not a collinear sliver.
  Mesh collapsed = unit_cube();
  collapsed.positions.push_back(collapsed.positions[0]);
  collapsed.normals.push_back({0, 0, 1});
  collapsed.triangles.push_back({0, 8, 1});
  collapsed.face_kinds.push_back(FaceKind::kLimit);
  const Mesh collapsed_before = collapsed;
  EXPECT_EQ(split_collinear_slivers(collapsed), 0u);
  EXPECT_EQ(collapsed, collapsed_before);
}

TEST(CollinearSlivers, SliverWithoutASingleNeighbourStays) {
  // With the triangle across the sliver's long edge 7-4 gone (the mesh is open there),
  // there is nothing to split: the sliver stays and nothing else moves.
  Mesh m = cube_with_sliver({0.5, 0.5, 1.0});
  m.triangles.erase(m.triangles.begin() + 3);  // (4, 7, 6), the sliver's neighbour
  m.face_kinds.erase(m.face_kinds.begin() + 3);
  const Mesh before = m;
  EXPECT_EQ(split_collinear_slivers(m), 0u);
  EXPECT_EQ(m, before);
}

}  // namespace
}  // namespace strielad
