// SPDX-License-Identifier: Apache-2.0
// Extracting a scene from a real store: skips decided from the index without reading
// bricks, only the scene's variables read, nodes of a level joining into one closed
// surface, coarse levels giving the same shape coarser.
#include <gtest/gtest.h>

#include <cmath>

#include "convert/converter.h"
#include "extract/level_extraction.h"
#include "extract/mesh_metrics.h"
#include "extract/node_extraction.h"
#include "scene/scene.h"
#include "store/store.h"
#include "support/expect_error.h"
#include "support/small_dataset.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

class SceneExtractionTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir();
    const auto data = testing::write_small_dataset(dir_->path(), 33, 29, 17, 1);
    build::convert(testing::small_convert_options(data, *dir_ / "store", 8));
  }
  static void TearDownTestSuite() { delete dir_; }

  std::shared_ptr<const Store> open() const { return Store::open(*dir_ / "store"); }
  ResolvedScene resolve(const Store& store, std::string_view json) const {
    return resolve_scene(parse_scene(json, "test scene"), store.manifest(), "test scene");
  }

  static testing::TempDir* dir_;
};
testing::TempDir* SceneExtractionTest::dir_ = nullptr;

TEST_F(SceneExtractionTest, NodesOfALevelJoinIntoOneClosedSurface) {
  // Faces shared between nodes are dropped; faces on the grid's edge stay.
  const auto store = open();
  const ResolvedScene scene = resolve(*store, R"({"time": 0, "subvolumes": [
      {"id": 4, "name": "cloud", "limits": [{"var": "cloud", "min": 1e-6}]}],
      "attributes": ["temp"]})");
  const LevelExtraction level = extract_level(*store, scene, {});
  std::uint64_t meshes = 0;
  for (const NodeExtraction& n : level.nodes) {
    for (const SubVolumeResult& r : n.results) {
      if (r.outcome != NodeOutcome::kMesh) continue;
      ++meshes;
      const MeshCheck c = check_mesh(r.mesh);
      EXPECT_TRUE(c.clean()) << "node " << n.node;
      ASSERT_EQ(r.mesh.attributes.size(), 1u);
      EXPECT_EQ(r.mesh.attribute_names[0], "temp");
    }
  }
  EXPECT_GT(meshes, 0u);
  const Mesh joined = seamless_union(level, 4);
  const MeshCheck c = check_mesh(joined);
  EXPECT_TRUE(c.closed()) << c.open_edges << " open, " << c.nonmanifold_edges << " non-manifold";
  EXPECT_GT(enclosed_volume(joined), 0.0);
}

TEST_F(SceneExtractionTest, ValueRangeSkipsReadNoBricks) {
  const auto store = open();
  // No cloud value reaches 1e30: every node is skipped from the index alone.
  const ResolvedScene scene = resolve(*store, R"({"time": 0, "subvolumes": [
      {"id": 1, "limits": [{"var": "cloud", "min": 1e30}]}]})");
  const LevelExtraction level = extract_level(*store, scene, {});
  EXPECT_EQ(level.totals.outcomes[static_cast<int>(NodeOutcome::kSkippedValueRange)] +
                level.totals.outcomes[static_cast<int>(NodeOutcome::kSkippedNoData)],
            level.totals.nodes);
  EXPECT_EQ(level.totals.chunks_read, 0u);
  EXPECT_EQ(level.totals.bricks_used, 0u);
  for (const NodeExtraction& n : level.nodes) {
    for (const SubVolumeResult& r : n.results) {
      if (r.outcome == NodeOutcome::kSkippedValueRange) {
        EXPECT_NE(r.reason.find("cloud"), std::string::npos) << r.reason;
      }
    }
  }
}

TEST_F(SceneExtractionTest, DomainBoxSkipsNodesOutsideIt) {
  const auto store = open();
  const auto& lon = store->manifest().x.values;
  const double cut = lon[3];  // only the first node column along lon
  const ResolvedScene scene = resolve(*store, fmt::format(R"({{"time": 0, "subvolumes": [
      {{"id": 1, "limits": [{{"var": "temp", "min": -1e9}}],
        "domain": {{"{}": [{}, {}]}}}}]}})",
                                                          store->manifest().x.name, lon[0], cut));
  const LevelExtraction level = extract_level(*store, scene, {});
  const auto skipped = level.totals.outcomes[static_cast<int>(NodeOutcome::kSkippedDomain)];
  EXPECT_GT(skipped, 0u);
  EXPECT_LT(skipped, level.totals.nodes);
  // Only the temp bricks of the nodes in the box are read.
  EXPECT_EQ(level.totals.bricks_used, level.totals.nodes - skipped);
}

TEST_F(SceneExtractionTest, OnlyTheScenesVariablesAreRead) {
  const auto store = open();
  const ResolvedScene scene = resolve(*store, R"({"time": 0, "subvolumes": [
      {"id": 1, "limits": [{"var": "temp", "max": 1e9}]}]})");
  const LevelExtraction level = extract_level(*store, scene, {});
  // One brick per node at most: temp only (never cloud or packed).
  EXPECT_LE(level.totals.bricks_used, level.totals.nodes);
}

TEST_F(SceneExtractionTest, CoarseLevelsGiveTheSameShapeCoarser) {
  const auto store = open();
  const ResolvedScene scene = resolve(*store, R"({"time": 0, "subvolumes": [
      {"id": 2, "limits": [{"var": "temp", "max": 280}]}]})");
  LevelExtractionOptions fine, coarse;
  coarse.level = 1;
  const double v0 = enclosed_volume(seamless_union(extract_level(*store, scene, fine), 2));
  const double v1 = enclosed_volume(seamless_union(extract_level(*store, scene, coarse), 2));
  ASSERT_NE(v0, 0.0);
  EXPECT_NEAR(v1 / v0, 1.0, 0.15);
}

TEST_F(SceneExtractionTest, BadLevelOrStepIsNamed) {
  const auto store = open();
  const ResolvedScene scene = resolve(*store, R"({"time": 0, "subvolumes": [
      {"id": 1, "limits": [{"var": "temp", "max": 1}]}]})");
  LevelExtractionOptions o;
  o.level = 99;
  testing::expect_error([&] { extract_level(*store, scene, o); }, ErrorCode::kInvalidArgument,
                        {"level 99"});
}

}  // namespace
}  // namespace strielad
