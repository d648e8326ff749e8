// SPDX-License-Identifier: Apache-2.0
// A store opened with direct reads returns the same bricks as a buffered one, fetches
// fewer bytes than the 4 KiB pages its chunks span, and still detects a damaged chunk
// by name while other nodes stay readable.
#include <gtest/gtest.h>

#include <fstream>

#include "convert/converter.h"
#include "core/direct_read_file.h"
#include "store/store.h"
#include "support/expect_error.h"
#include "support/small_dataset.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using testing::expect_error;

class DirectReadsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto data = testing::write_small_dataset(dir_.path(), 41, 37, 19, 1);
    build::convert(testing::small_convert_options(data, store_path()));
    if (!DirectReadFile::open(store_path() / format::step_file_name(0))) {
      GTEST_SKIP() << "the file system under " << dir_.path() << " has no O_DIRECT";
    }
  }
  std::filesystem::path store_path() const { return dir_ / "store"; }
  testing::TempDir dir_;
};

TEST_F(DirectReadsTest, BricksEqualBufferedReads) {
  const auto buffered = Store::open(store_path());
  const auto direct = Store::open(store_path(), StoreOpenOptions{.direct_reads = true});
  std::size_t data_bricks = 0;
  std::uint64_t page_bytes = 0;
  for (std::uint32_t v = 0; v < buffered->variable_count(); ++v) {
    const auto entries = buffered->index(0, v);
    for (NodeId n = 0; n < entries.size(); ++n) {
      const Brick a = buffered->read_brick(0, v, n);
      const Brick b = direct->read_brick(0, v, n);
      ASSERT_EQ(a.kind, b.kind) << buffered->describe_node(v, n);
      ASSERT_EQ(a.bytes, b.bytes) << buffered->describe_node(v, n);
      if (entries[n].kind == format::BrickKind::kData) {
        ++data_bricks;
        const std::uint64_t first = entries[n].chunk_offset / 4096;
        const std::uint64_t last = (entries[n].chunk_offset + entries[n].chunk_size - 1) / 4096;
        page_bytes += (last - first + 1) * 4096;
      }
    }
  }
  ASSERT_GT(data_bricks, 3u);
  const StoreReadCounters c = direct->counters();
  EXPECT_EQ(c.chunks_read, data_bricks);
  EXPECT_GE(c.direct_bytes, c.chunk_bytes);
  EXPECT_LT(c.direct_bytes, page_bytes);  // sub-page blocks, not whole pages
  EXPECT_EQ(buffered->counters().direct_bytes, 0u);
}

TEST_F(DirectReadsTest, DamagedChunkIsNamedAndOthersStayReadable) {
  auto store = Store::open(store_path());
  const auto entries = store->index(0, 0);
  std::vector<NodeId> data;
  for (NodeId n = 0; n < entries.size(); ++n) {
    if (entries[n].kind == format::BrickKind::kData) data.push_back(n);
  }
  ASSERT_GE(data.size(), 2u);
  const NodeId victim = data.front();
  {
    const auto path = store_path() / format::step_file_name(0);
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    const auto at = static_cast<std::streamoff>(entries[victim].chunk_offset + 1);
    f.seekg(at);
    char c;
    f.get(c);
    f.seekp(at);
    f.put(static_cast<char>(c ^ 0x21));
  }
  store = Store::open(store_path(), StoreOpenOptions{.direct_reads = true});
  expect_error([&] { store->read_brick(0, 0, victim); }, ErrorCode::kCorrupt,
               {"step-000000.bricks", fmt::format("node {} ", victim), "chunk checksum mismatch"});
  EXPECT_NO_THROW(store->read_brick(0, 0, data.back()));
}

}  // namespace
}  // namespace strielad
