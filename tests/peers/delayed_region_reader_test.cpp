// SPDX-License-Identifier: Apache-2.0
// Reading bricks through OpenVDB delayed loading (the io benchmark's OpenVDB contender)
// returns the store's own level-0 samples (fill and background read as the background),
// loads only the leaves a read touches, and names a missing file or grid.
#include <gtest/gtest.h>

#include <cmath>

#include "convert/converter.h"
#include "core/error.h"
#include "store/store.h"
#include "support/small_dataset.h"
#include "support/temp_dir.h"
#include "peers/delayed_region_reader.h"
#include "vdb/level_grid.h"

namespace strielad {
namespace {

TEST(DelayedRegionReaderTest, BoxesEqualTheStoresBricksAndLoadOnlyWhatTheyTouch) {
  testing::TempDir dir;
  const auto data = testing::write_small_dataset(dir.path(), 40, 36, 20, 1);
  build::convert(testing::small_convert_options(data, dir / "store", 8));
  const auto store = Store::open(dir / "store");
  std::vector<std::filesystem::path> files;
  std::vector<std::string> grids;
  for (std::uint32_t v = 0; v < store->variable_count(); ++v) {
    grids.push_back(store->manifest().variables[v].name);
    files.push_back(dir / (grids.back() + ".vdb"));
    vdb::write_level_vdb(*store, 0, v, 0, files.back());
  }
  peers::DelayedRegionReader reader(files, grids);
  const std::size_t unloaded_at_open = reader.unloaded_leaves();
  EXPECT_GT(unloaded_at_open, 0u);

  const auto& shape = store->octree().level(0);
  std::vector<float> out;
  std::size_t compared = 0;
  for (std::uint32_t v = 0; v < store->variable_count(); ++v) {
    for (NodeId n = shape.first_node; n < shape.first_node + shape.node_count(); n += 3) {
      const Brick b = store->read_brick(0, v, n);
      reader.read_box(v, b.box, out);
      ASSERT_EQ(out.size(), b.dims[0] * b.dims[1] * b.dims[2]);
      for (std::size_t i = 0; i < out.size(); ++i) {
        const double s = b.sample(i);
        EXPECT_EQ(out[i], std::isnan(s) ? 0.0f : static_cast<float>(s)) << grids[v] << " node " << n;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 0u);
  EXPECT_LT(reader.unloaded_leaves(), unloaded_at_open);
}

TEST(DelayedRegionReaderTest, NamesAMissingFileOrGrid) {
  testing::TempDir dir;
  try {
    peers::DelayedRegionReader reader({dir / "absent.vdb"}, {"clw"});
    FAIL() << "opened a missing file";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kNotFound);
    EXPECT_NE(std::string(e.what()).find("absent.vdb"), std::string::npos);
  }
  const auto data = testing::write_small_dataset(dir.path(), 20, 18, 10, 1);
  build::convert(testing::small_convert_options(data, dir / "store", 8));
  const auto store = Store::open(dir / "store");
  vdb::write_level_vdb(*store, 0, 0, 0, dir / "one.vdb");
  try {
    peers::DelayedRegionReader reader({dir / "one.vdb"}, {"no-such-grid"});
    FAIL() << "found a missing grid";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kNotFound);
    EXPECT_NE(std::string(e.what()).find("no-such-grid"), std::string::npos);
  }
}

}  // namespace
}  // namespace strielad
