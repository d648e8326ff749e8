// SPDX-License-Identifier: Apache-2.0
// export-vdb writes a standard .vdb whose active voxels are exactly the store's valid,
// non-background samples of the chosen level, with metadata naming variable and time.
#include <gtest/gtest.h>
#include <openvdb/io/File.h>

#include <cmath>
#include <set>

#include "convert/converter.h"
#include "store/store.h"
#include "support/small_dataset.h"
#include "support/temp_dir.h"
#include "vdb/level_grid_openvdb.h"

namespace strielad {
namespace {

TEST(ExportLevelVdbTest, ActiveVoxelsEqualTheLevelsNonBackgroundSamples) {
  testing::TempDir dir;
  const auto data = testing::write_small_dataset(dir.path(), 30, 20, 10, 1);
  build::convert(testing::small_convert_options(data, dir / "store", 4));
  const auto store = Store::open(dir / "store");
  const auto var = static_cast<std::uint32_t>(store->manifest().variable_index("cloud"));
  for (std::uint32_t level : {0u, 1u}) {
    const auto out = dir / ("cloud-" + std::to_string(level) + ".vdb");
    const auto summary = vdb::write_level_vdb(*store, 0, var, level, out);

    openvdb::initialize();
    openvdb::io::File file(out.string());
    file.open();
    auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("cloud"));
    file.close();
    ASSERT_TRUE(grid);
    EXPECT_EQ(grid->metaValue<std::string>("strielad:variable"), "cloud");
    EXPECT_EQ(grid->metaValue<openvdb::Int64>("strielad:level"), level);
    EXPECT_EQ(grid->voxelSize()[0], double(store->octree().level(level).stride[0]));

    // Count what should be active from the bricks of that level (shared samples once).
    const auto& shape = store->octree().level(level);
    std::set<std::array<std::size_t, 3>> expected;
    auto accessor = grid->getConstAccessor();
    for (NodeId n = shape.first_node; n < shape.first_node + shape.node_count(); ++n) {
      const Brick b = store->read_brick(0, var, n);
      for (std::size_t z = 0; z < b.dims[2]; ++z)
        for (std::size_t y = 0; y < b.dims[1]; ++y)
          for (std::size_t x = 0; x < b.dims[0]; ++x) {
            const double v = b.sample((z * b.dims[1] + y) * b.dims[0] + x);
            const openvdb::Coord c(int(b.box.lo[0] + x), int(b.box.lo[1] + y), int(b.box.lo[2] + z));
            if (std::isnan(v) || v == 0.0) {
              EXPECT_FALSE(accessor.isValueOn(c)) << c;
              continue;
            }
            expected.insert({b.box.lo[0] + x, b.box.lo[1] + y, b.box.lo[2] + z});
            EXPECT_TRUE(accessor.isValueOn(c)) << c;
            EXPECT_EQ(accessor.getValue(c), static_cast<float>(v)) << c;
          }
    }
    EXPECT_GT(expected.size(), 0u);
    EXPECT_EQ(grid->activeVoxelCount(), expected.size()) << "level " << level;
    EXPECT_EQ(summary.active_voxels, expected.size());
  }
}

TEST(ExportLevelVdbTest, MissingLevelIsAClearError) {
  testing::TempDir dir;
  const auto data = testing::write_small_dataset(dir.path(), 12, 10, 6, 1);
  build::convert(testing::small_convert_options(data, dir / "store", 4));
  const auto store = Store::open(dir / "store");
  try {
    vdb::write_level_vdb(*store, 0, 0, 99, dir / "x.vdb");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kNotFound);
    EXPECT_NE(std::string(e.what()).find("level 99 does not exist"), std::string::npos);
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "x.vdb"));
}

}  // namespace
}  // namespace strielad
