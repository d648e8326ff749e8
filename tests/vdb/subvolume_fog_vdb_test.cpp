// SPDX-License-Identifier: Apache-2.0
// A sub-volume exported as a fog volume: density 1 exactly at the samples where every
// limit holds inside the domain box, one grid per sub-volume, nodes excluded by their
// value range skipped without reading.
#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <cmath>

#include "build/converter.h"
#include "scene/scene.h"
#include "store/store.h"
#include "support/small_dataset.h"
#include "support/temp_dir.h"
#include "vdb/level_grid.h"

namespace strielad {
namespace {

TEST(SubvolumeFogVdbTest, ActiveVoxelsAreTheSamplesInsideTheSubvolume) {
  testing::TempDir dir;
  const auto data = testing::write_small_dataset(dir.path(), 30, 20, 10, 1);
  build::convert(testing::small_convert_options(data, dir / "store", 4));
  const auto store = Store::open(dir / "store");
  const auto scene = resolve_scene(parse_scene(R"({"subvolumes": [
      {"id": 3, "name": "warm", "limits": [{"var": "temp", "min": 270}]},
      {"id": 5, "limits": [{"var": "cloud", "min": 1e30}]}]})", "scene"),
                                   store->manifest(), "scene");
  const auto out = dir / "sub.vdb";
  const auto summaries = vdb::write_subvolume_vdb(*store, scene, 0, out);
  ASSERT_EQ(summaries.size(), 2u);
  EXPECT_EQ(summaries[1].bricks_read, 0u);  // no cloud reaches 1e30: all skipped
  EXPECT_EQ(summaries[1].active_voxels, 0u);

  openvdb::initialize();
  openvdb::io::File file(out.string());
  file.open();
  auto warm = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("warm"));
  auto none = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("subvolume-5"));
  file.close();
  ASSERT_TRUE(warm);
  ASSERT_TRUE(none);
  EXPECT_EQ(warm->getGridClass(), openvdb::GRID_FOG_VOLUME);
  // Count the samples with temp >= 270 from the level-0 bricks (shared samples once).
  const auto var = static_cast<std::uint32_t>(store->manifest().variable_index("temp"));
  std::uint64_t expected = 0;
  const auto& shape = store->octree().level(0);
  std::vector<char> seen(data.nx * data.ny * data.nz, 0);
  for (NodeId n = shape.first_node; n < shape.first_node + shape.node_count(); ++n) {
    const Brick b = store->read_brick(0, var, n);
    for (std::size_t z = 0; z < b.dims[2]; ++z)
      for (std::size_t y = 0; y < b.dims[1]; ++y)
        for (std::size_t x = 0; x < b.dims[0]; ++x) {
          const std::size_t g = ((b.box.lo[2] + z) * data.ny + b.box.lo[1] + y) * data.nx +
                                b.box.lo[0] + x;
          if (seen[g]) continue;
          seen[g] = 1;
          expected += b.sample((z * b.dims[1] + y) * b.dims[0] + x) >= 270;
        }
  }
  EXPECT_GT(expected, 0u);
  EXPECT_EQ(warm->activeVoxelCount(), expected);
  EXPECT_EQ(summaries[0].active_voxels, expected);
  EXPECT_EQ(none->activeVoxelCount(), 0u);
}

}  // namespace
}  // namespace strielad
