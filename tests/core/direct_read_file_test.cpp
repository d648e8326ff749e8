// SPDX-License-Identifier: Apache-2.0
// Direct reads return exactly the bytes a buffered read returns, at any offset and
// length (unaligned starts, ends in the file's last partial block), fetch only the
// 512-byte blocks they span, and name the file when a read runs past its end.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <vector>

#include "core/direct_read_file.h"
#include "core/file_io.h"
#include "support/expect_error.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using testing::expect_error;

class DirectReadFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // 3 pages and a bit: the last block is partial.
    bytes_.resize(3 * 4096 + 777);
    std::mt19937 rng(7);
    for (auto& b : bytes_) b = static_cast<std::byte>(rng());
    path_ = dir_ / "data.bin";
    std::ofstream(path_, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes_.data()), static_cast<std::streamsize>(bytes_.size()));
    file_ = DirectReadFile::open(path_);
    if (!file_) GTEST_SKIP() << "the file system under " << dir_.path() << " has no O_DIRECT";
  }
  testing::TempDir dir_;
  std::filesystem::path path_;
  std::vector<std::byte> bytes_;
  std::unique_ptr<DirectReadFile> file_;
};

TEST_F(DirectReadFileTest, EveryRangeEqualsTheFileBytes) {
  const ReadOnlyFile buffered(path_);
  std::mt19937 rng(11);
  const std::vector<std::pair<std::uint64_t, std::size_t>> fixed = {
      {0, 1}, {0, 512}, {511, 2}, {4095, 4098}, {bytes_.size() - 1, 1}, {0, bytes_.size()},
      {bytes_.size() - 777, 777}, {12000, bytes_.size() - 12000}};
  std::vector<std::pair<std::uint64_t, std::size_t>> ranges = fixed;
  for (int i = 0; i < 200; ++i) {
    const std::uint64_t offset = rng() % bytes_.size();
    ranges.emplace_back(offset, 1 + rng() % (bytes_.size() - offset));
  }
  for (const auto& [offset, length] : ranges) {
    std::vector<std::byte> direct(length), expected(length);
    file_->read_at(offset, direct);
    buffered.read_at(offset, expected);
    ASSERT_EQ(direct, expected) << "offset " << offset << " length " << length;
  }
}

TEST_F(DirectReadFileTest, FetchesOnlyTheBlocksARangeSpans) {
  std::vector<std::byte> out(100);
  const std::uint64_t fetched = file_->read_at(1000, out);  // crosses the block edge at 1024
  EXPECT_EQ(fetched % file_->alignment(), 0u);
  EXPECT_LE(fetched, 1024u);  // one or two 512-byte blocks, never a whole 4 KiB page span
  if (file_->alignment() == 512) {
    EXPECT_EQ(fetched, 1024u);  // blocks [512, 1536)
  }
  std::vector<std::byte> small(10);
  EXPECT_EQ(file_->read_at(4096 + 600, small), file_->alignment());
}

TEST_F(DirectReadFileTest, ReadPastTheEndIsTruncatedAndNamesTheFile) {
  std::vector<std::byte> out(10);
  expect_error([&] { file_->read_at(bytes_.size() - 5, out); }, ErrorCode::kTruncated,
               {"data.bin", "file has only"});
}

TEST(DirectReadFileOpen, MissingFileIsNotFound) {
  testing::TempDir dir;
  expect_error([&] { DirectReadFile::open(dir / "absent.bin"); }, ErrorCode::kNotFound,
               {"absent.bin"});
}

}  // namespace
}  // namespace strielad
