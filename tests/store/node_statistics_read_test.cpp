// SPDX-License-Identifier: Apache-2.0
// Node statistics come from the index alone (no brick bytes are read), and a brick is
// fetched with exactly one read of exactly its chunk.
#include <gtest/gtest.h>

#include "convert/converter.h"
#include "store/brick_cache.h"
#include "store/store.h"
#include "support/small_dataset.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

TEST(NodeStatisticsReadTest, StatisticsNeverTouchBrickData) {
  testing::TempDir dir;
  const auto data = testing::write_small_dataset(dir.path(), 40, 30, 12, 2);
  build::convert(testing::small_convert_options(data, dir / "store"));
  const auto store = Store::open(dir / "store");
  std::uint64_t nonempty = 0;
  for (std::uint32_t t = 0; t < 2; ++t) {
    for (NodeId n = 0; n < store->octree().node_count(); ++n) {
      nonempty += store->node_entry(t, 0, n).valid_count > 0;
    }
  }
  EXPECT_GT(nonempty, 0u);
  const auto c = store->counters();
  EXPECT_EQ(c.chunks_read, 0u);
  EXPECT_EQ(c.chunk_bytes, 0u);
  // Only variable 0's index sections (plus headers, footers, tables) were read.
  const auto file_size = std::filesystem::file_size(store->step_path(0));
  EXPECT_LT(c.index_bytes, file_size / 4);
}

TEST(NodeStatisticsReadTest, OneBrickIsOneReadOfItsChunk) {
  testing::TempDir dir;
  const auto data = testing::write_small_dataset(dir.path(), 40, 30, 12, 1);
  build::convert(testing::small_convert_options(data, dir / "store"));
  const auto store = Store::open(dir / "store");
  const auto entries = store->index(0, 1);
  for (NodeId n = 0; n < entries.size(); ++n) {
    if (entries[n].kind != format::BrickKind::kData) continue;
    const auto before = store->counters();
    store->read_brick(0, 1, n);
    const auto after = store->counters();
    EXPECT_EQ(after.chunks_read - before.chunks_read, 1u);
    EXPECT_EQ(after.chunk_bytes - before.chunk_bytes, entries[n].chunk_size);
    EXPECT_EQ(after.index_bytes, before.index_bytes);
  }
}

TEST(NodeStatisticsReadTest, ConstantAndEmptyBricksNeedNoRead) {
  testing::TempDir dir;
  const auto data = testing::write_small_dataset(dir.path(), 40, 30, 12, 1);
  build::convert(testing::small_convert_options(data, dir / "store"));
  const auto store = Store::open(dir / "store");
  const auto entries = store->index(0, 0);
  BrickCache cache(1 << 20);
  std::size_t checked = 0;
  for (NodeId n = 0; n < entries.size(); ++n) {
    if (entries[n].kind == format::BrickKind::kData) continue;
    const Brick b = *store->read_brick(0, 0, n, cache);
    EXPECT_EQ(b.bytes.size(), 0u);
    ++checked;
  }
  EXPECT_GT(checked, 0u);
  EXPECT_EQ(store->counters().chunks_read, 0u);
}

}  // namespace
}  // namespace strielad
