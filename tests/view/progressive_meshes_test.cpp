// SPDX-License-Identifier: Apache-2.0
// view::ProgressiveMeshes without a GPU or a server: which mesh each node of the cut
// shows while results stream in (nothing before its first result, stale meshes across
// a generation change, no mesh for a node that left and came back), refused results
// for nodes outside the cut, empty results, and the pending/complete/version counters.
#include <gtest/gtest.h>

#include <initializer_list>
#include <memory>

#include "view/progressive_meshes.h"

namespace strielad::view {
namespace {

// A mesh of `triangles` triangles (one vertex per corner, all at the origin).
std::shared_ptr<const NodeGeometry> mesh(NodeId node, std::size_t triangles = 1) {
  auto g = std::make_shared<NodeGeometry>();
  g->node = node;
  g->vertices.assign(3 * triangles * kVertexFloats, 0.0f);
  for (std::uint32_t i = 0; i < 3 * triangles; ++i) g->indices.push_back(i);
  return g;
}

lod::CutDiff added(std::initializer_list<NodeId> nodes) {
  lod::CutDiff diff;
  float priority = 1;
  for (const NodeId n : nodes) diff.added.push_back({n, priority++});
  return diff;
}

lod::CutDiff removed(std::initializer_list<NodeId> nodes) {
  lod::CutDiff diff;
  diff.removed.assign(nodes.begin(), nodes.end());
  return diff;
}

const ProgressiveMeshes::Entry& entry(const ProgressiveMeshes& meshes, NodeId node) {
  const auto it = meshes.entries().find(node);
  EXPECT_NE(it, meshes.entries().end()) << "node " << node << " has no entry";
  static const ProgressiveMeshes::Entry none;
  return it == meshes.entries().end() ? none : it->second;
}

TEST(ProgressiveMeshes, ANodeAddedToTheCutShowsNothingUntilAccepted) {
  ProgressiveMeshes meshes;
  meshes.apply_cut_diff(added({4, 9}));
  ASSERT_EQ(meshes.size(), 2u);
  for (const NodeId n : {4u, 9u}) {
    EXPECT_EQ(entry(meshes, n).mesh, nullptr) << "node " << n;
    EXPECT_FALSE(entry(meshes, n).current) << "node " << n;
  }
  EXPECT_EQ(meshes.pending(), 2u);
  EXPECT_EQ(meshes.stale_shown(), 0u);
  EXPECT_FALSE(meshes.complete());

  const auto m4 = mesh(4);
  EXPECT_TRUE(meshes.accept(4, m4));
  EXPECT_EQ(entry(meshes, 4).mesh, m4);
  EXPECT_TRUE(entry(meshes, 4).current);
  EXPECT_EQ(entry(meshes, 9).mesh, nullptr);
  EXPECT_FALSE(entry(meshes, 9).current);
  EXPECT_EQ(meshes.pending(), 1u);
  EXPECT_FALSE(meshes.complete());

  EXPECT_TRUE(meshes.accept(9, mesh(9)));
  EXPECT_EQ(meshes.pending(), 0u);
  EXPECT_TRUE(meshes.complete());
}

TEST(ProgressiveMeshes, BeginGenerationKeepsEveryMeshButMarksItStale) {
  ProgressiveMeshes meshes;
  meshes.apply_cut_diff(added({1, 2, 3}));
  const auto m1 = mesh(1), m2 = mesh(2);
  meshes.accept(1, m1);
  meshes.accept(2, m2);
  meshes.accept(3, nullptr);
  ASSERT_TRUE(meshes.complete());
  ASSERT_EQ(meshes.stale_shown(), 0u);

  meshes.begin_generation();
  EXPECT_EQ(meshes.size(), 3u);
  EXPECT_EQ(entry(meshes, 1).mesh, m1);
  EXPECT_EQ(entry(meshes, 2).mesh, m2);
  EXPECT_EQ(entry(meshes, 3).mesh, nullptr);
  for (const NodeId n : {1u, 2u, 3u}) EXPECT_FALSE(entry(meshes, n).current) << "node " << n;
  EXPECT_EQ(meshes.stale_shown(), 2u);  // node 3 shows nothing, so it is not counted
  EXPECT_EQ(meshes.pending(), 3u);
  EXPECT_FALSE(meshes.complete());

  // The new generation's answers replace the stale meshes one by one.
  const auto m1b = mesh(1, 2);
  EXPECT_TRUE(meshes.accept(1, m1b));
  EXPECT_EQ(entry(meshes, 1).mesh, m1b);
  EXPECT_TRUE(entry(meshes, 1).current);
  EXPECT_EQ(entry(meshes, 2).mesh, m2);  // still the stale one
  EXPECT_EQ(meshes.stale_shown(), 1u);
  EXPECT_EQ(meshes.pending(), 2u);

  EXPECT_TRUE(meshes.accept(2, mesh(2, 3)));
  EXPECT_EQ(meshes.stale_shown(), 0u);
  EXPECT_FALSE(meshes.complete());
  EXPECT_TRUE(meshes.accept(3, nullptr));
  EXPECT_TRUE(meshes.complete());
}

TEST(ProgressiveMeshes, ANodeRemovedFromTheCutLosesItsMesh) {
  ProgressiveMeshes meshes;
  meshes.apply_cut_diff(added({1, 2}));
  meshes.accept(1, mesh(1));
  meshes.accept(2, mesh(2));
  meshes.apply_cut_diff(removed({1}));
  EXPECT_EQ(meshes.size(), 1u);
  EXPECT_FALSE(meshes.entries().contains(1));
  EXPECT_TRUE(meshes.entries().contains(2));
  EXPECT_TRUE(meshes.complete());
  EXPECT_EQ(meshes.pending(), 0u);
}

TEST(ProgressiveMeshes, ARemovedPendingNodeNoLongerCountsAsPending) {
  ProgressiveMeshes meshes;
  meshes.apply_cut_diff(added({1, 2}));
  meshes.accept(2, mesh(2));
  ASSERT_EQ(meshes.pending(), 1u);
  meshes.apply_cut_diff(removed({1}));
  EXPECT_EQ(meshes.pending(), 0u);
  EXPECT_TRUE(meshes.complete());
}

TEST(ProgressiveMeshes, ANodeReaddedToTheCutShowsNoMeshItHadBefore) {
  ProgressiveMeshes meshes;
  meshes.apply_cut_diff(added({5, 6}));
  meshes.accept(5, mesh(5));
  meshes.accept(6, mesh(6));
  meshes.apply_cut_diff(removed({5}));
  meshes.apply_cut_diff(added({5}));
  EXPECT_EQ(entry(meshes, 5).mesh, nullptr);
  EXPECT_FALSE(entry(meshes, 5).current);
  EXPECT_EQ(meshes.stale_shown(), 0u);
  EXPECT_EQ(meshes.pending(), 1u);
  EXPECT_FALSE(meshes.complete());
}

TEST(ProgressiveMeshes, ANodeReaddedDuringAGenerationChangeShowsNoStaleMesh) {
  ProgressiveMeshes meshes;
  meshes.apply_cut_diff(added({5, 6}));
  meshes.accept(5, mesh(5));
  meshes.accept(6, mesh(6));
  meshes.begin_generation();
  ASSERT_EQ(meshes.stale_shown(), 2u);
  meshes.apply_cut_diff(removed({5}));
  meshes.apply_cut_diff(added({5}));
  EXPECT_EQ(entry(meshes, 5).mesh, nullptr);
  EXPECT_EQ(meshes.stale_shown(), 1u);  // only node 6's
  EXPECT_EQ(meshes.pending(), 2u);
}

TEST(ProgressiveMeshes, AcceptForANodeNotInTheCutIsRefusedAndChangesNothing) {
  ProgressiveMeshes meshes;
  meshes.apply_cut_diff(added({1, 2}));
  const auto m1 = mesh(1);
  meshes.accept(1, m1);
  const auto version = meshes.version();

  EXPECT_FALSE(meshes.accept(3, mesh(3)));
  EXPECT_FALSE(meshes.accept(3, nullptr));
  EXPECT_EQ(meshes.size(), 2u);
  EXPECT_FALSE(meshes.entries().contains(3));
  EXPECT_EQ(meshes.pending(), 1u);
  EXPECT_EQ(meshes.version(), version);
  EXPECT_EQ(entry(meshes, 1).mesh, m1);

  // A node that left the cut: its late result is refused too.
  meshes.apply_cut_diff(removed({1}));
  const auto after_removal = meshes.version();
  EXPECT_FALSE(meshes.accept(1, mesh(1)));
  EXPECT_FALSE(meshes.entries().contains(1));
  EXPECT_EQ(meshes.version(), after_removal);
  EXPECT_EQ(meshes.pending(), 1u);
}

TEST(ProgressiveMeshes, ANullOrEmptyMeshIsACurrentNodeShowingNothing) {
  ProgressiveMeshes meshes;
  meshes.apply_cut_diff(added({1, 2}));
  EXPECT_TRUE(meshes.accept(1, nullptr));
  EXPECT_TRUE(meshes.accept(2, std::make_shared<NodeGeometry>()));
  EXPECT_TRUE(meshes.complete());
  for (const NodeId n : {1u, 2u}) {
    const auto& e = entry(meshes, n);
    EXPECT_TRUE(e.current) << "node " << n;
    EXPECT_TRUE(e.mesh == nullptr || e.mesh->empty()) << "node " << n;
  }
  // Nothing is shown, so nothing is stale after a generation change either.
  meshes.begin_generation();
  EXPECT_EQ(meshes.stale_shown(), 0u);
}

TEST(ProgressiveMeshes, AnEmptyResultReplacesAStaleMesh) {
  ProgressiveMeshes meshes;
  meshes.apply_cut_diff(added({1}));
  meshes.accept(1, mesh(1));
  meshes.begin_generation();
  ASSERT_EQ(meshes.stale_shown(), 1u);
  EXPECT_TRUE(meshes.accept(1, std::make_shared<NodeGeometry>()));
  EXPECT_TRUE(entry(meshes, 1).current);
  EXPECT_TRUE(entry(meshes, 1).mesh == nullptr || entry(meshes, 1).mesh->empty());
  EXPECT_EQ(meshes.stale_shown(), 0u);
  EXPECT_TRUE(meshes.complete());
}

TEST(ProgressiveMeshes, AcceptingANodeTwiceCountsItOnce) {
  ProgressiveMeshes meshes;
  meshes.apply_cut_diff(added({1, 2}));
  meshes.accept(1, mesh(1));
  const auto m1b = mesh(1, 4);
  EXPECT_TRUE(meshes.accept(1, m1b));
  EXPECT_EQ(entry(meshes, 1).mesh, m1b);
  EXPECT_EQ(meshes.pending(), 1u);
  EXPECT_FALSE(meshes.complete());
}

TEST(ProgressiveMeshes, AnEmptyCutIsComplete) {
  ProgressiveMeshes meshes;
  EXPECT_EQ(meshes.size(), 0u);
  EXPECT_EQ(meshes.pending(), 0u);
  EXPECT_EQ(meshes.stale_shown(), 0u);
  EXPECT_TRUE(meshes.complete());
}

TEST(ProgressiveMeshes, VersionIncreasesOnEveryChangeOfWhatIsShown) {
  ProgressiveMeshes meshes;
  auto last = meshes.version();
  const auto expect_increased = [&](const char* what) {
    EXPECT_GT(meshes.version(), last) << what;
    last = meshes.version();
  };
  meshes.apply_cut_diff(added({1, 2}));
  expect_increased("nodes added");
  meshes.accept(1, mesh(1));
  expect_increased("a mesh accepted");
  meshes.accept(2, nullptr);
  expect_increased("an empty result accepted");
  meshes.begin_generation();
  expect_increased("generation started");
  meshes.accept(1, mesh(1));
  expect_increased("a stale mesh replaced");
  meshes.apply_cut_diff(removed({2}));
  expect_increased("a node removed");
  meshes.clear();
  expect_increased("cleared");
}

TEST(ProgressiveMeshes, ClearForgetsEveryNode) {
  ProgressiveMeshes meshes;
  meshes.apply_cut_diff(added({1, 2}));
  meshes.accept(1, mesh(1));
  meshes.clear();
  EXPECT_EQ(meshes.size(), 0u);
  EXPECT_TRUE(meshes.entries().empty());
  EXPECT_EQ(meshes.pending(), 0u);
  EXPECT_TRUE(meshes.complete());
  EXPECT_FALSE(meshes.accept(1, mesh(1)));
}

TEST(ProgressiveMeshes, RemovingANodeNotInTheCutChangesNothing) {
  ProgressiveMeshes meshes;
  meshes.apply_cut_diff(added({1}));
  const auto m1 = mesh(1);
  meshes.accept(1, m1);
  meshes.apply_cut_diff(removed({7}));
  EXPECT_EQ(meshes.size(), 1u);
  EXPECT_EQ(entry(meshes, 1).mesh, m1);
  EXPECT_TRUE(meshes.complete());
}

}  // namespace
}  // namespace strielad::view
