// SPDX-License-Identifier: Apache-2.0
// Damage to a store is detected and named (file, variable, node); a damaged chunk does
// not stop reads of other nodes; verify lists every problem.
#include <gtest/gtest.h>

#include <fstream>

#include "convert/converter.h"
#include "support/expect_error.h"
#include "store/store.h"
#include "store/store_verifier.h"
#include "support/small_dataset.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using testing::expect_error;

class StoreCorruptionTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto data = testing::write_small_dataset(dir_.path(), 23, 17, 11, 2);
    build::convert(testing::small_convert_options(data, store_path()));
  }
  std::filesystem::path store_path() const { return dir_ / "store"; }
  std::filesystem::path step_file(int s) const {
    return store_path() / format::step_file_name(static_cast<std::uint32_t>(s));
  }
  void flip_byte(const std::filesystem::path& file, std::uint64_t offset) {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(static_cast<std::streamoff>(offset));
    char c;
    f.get(c);
    f.seekp(static_cast<std::streamoff>(offset));
    f.put(static_cast<char>(c ^ 0x5a));
  }
  testing::TempDir dir_;
};

TEST_F(StoreCorruptionTest, BitFlipInAChunkIsNamedAndOtherNodesStayReadable) {
  auto store = Store::open(store_path());
  const auto entries = store->index(1, 0);
  NodeId victim = 0, other = 0;
  bool found = false;
  for (NodeId n = 0; n < entries.size(); ++n) {
    if (entries[n].kind != format::BrickKind::kData) continue;
    if (!found) {
      victim = n;
      found = true;
    } else {
      other = n;
    }
  }
  ASSERT_TRUE(found && other != victim);
  flip_byte(step_file(1), entries[victim].chunk_offset + entries[victim].chunk_size / 2);
  store = Store::open(store_path());
  expect_error([&] { store->read_brick(1, 0, victim); }, ErrorCode::kCorrupt,
               {"step-000001.bricks", fmt::format("node {} ", victim), "variable 'cloud'",
                "chunk checksum mismatch"});
  EXPECT_NO_THROW(store->read_brick(1, 0, other));
  EXPECT_NO_THROW(store->read_brick(0, 0, victim));

  const VerifyReport report = verify_store(store_path());
  ASSERT_EQ(report.problems.size(), 1u);
  EXPECT_NE(report.problems[0].find(fmt::format("node {} ", victim)), std::string::npos);
}

TEST_F(StoreCorruptionTest, TruncatedStepFileIsDetected) {
  const auto size = std::filesystem::file_size(step_file(0));
  std::filesystem::resize_file(step_file(0), size - 10);
  const auto store = Store::open(store_path());
  expect_error([&] { store->index(0, 0); }, ErrorCode::kCorrupt, {"step-000000.bricks"});
  EXPECT_NO_THROW(store->index(1, 0));
  EXPECT_FALSE(verify_store(store_path()).ok());
}

TEST_F(StoreCorruptionTest, BitFlipInAnIndexSectionIsDetected) {
  auto store = Store::open(store_path());
  store->index(0, 1);  // find where variable 1's section is by decoding the footer
  const auto size = std::filesystem::file_size(step_file(0));
  // The last index section ends right before the section table (3 x 48 bytes + footer).
  flip_byte(step_file(0), size - 64 - 3 * 48 - 5);
  store = Store::open(store_path());
  expect_error([&] { store->index(0, 2); }, ErrorCode::kCorrupt,
               {"variable 'packed'", "index section checksum mismatch"});
  EXPECT_NO_THROW(store->index(0, 0));
}

TEST_F(StoreCorruptionTest, WrongVersionAndBadMagicAreRejected) {
  {
    std::fstream f(step_file(0), std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(8);
    f.put(5);
  }
  const auto store = Store::open(store_path());
  expect_error([&] { store->index(0, 0); }, ErrorCode::kVersionTooNew,
               {"step-000000.bricks", "version 5 is newer than this reader (max 1)"});
  flip_byte(step_file(1), std::filesystem::file_size(step_file(1)) - 2);
  expect_error([&] { store->index(1, 0); }, ErrorCode::kCorrupt, {"step-000001.bricks", "bad magic"});
}

TEST_F(StoreCorruptionTest, DamagedManifestIsRejected) {
  flip_byte(store_path() / "MANIFEST", 200);
  expect_error([&] { Store::open(store_path()); }, ErrorCode::kCorrupt, {"MANIFEST", "checksum"});
  const VerifyReport report = verify_store(store_path());
  EXPECT_FALSE(report.ok());
}

TEST_F(StoreCorruptionTest, StepFileFromAnotherStoreIsRejected) {
  std::filesystem::create_directories(dir_ / "other");
  const auto other = testing::write_small_dataset(dir_ / "other", 23, 17, 11, 2);
  auto opts = testing::small_convert_options(other, dir_ / "other-store");
  opts.codec.name = "lz4";  // same data, different plan (default codec is zstd)
  build::convert(opts);
  std::filesystem::copy_file(dir_ / "other-store" / format::step_file_name(0), step_file(0),
                             std::filesystem::copy_options::overwrite_existing);
  // A finalized store notices the foreign file by its recorded size or footer...
  const auto store = Store::open(store_path());
  expect_error([&] { store->index(0, 0); }, ErrorCode::kCorrupt, {"step-000000.bricks"});
  // ...and an unfinalized one by the store id in the step header.
  auto unfinalized = testing::small_convert_options(other, dir_ / "third-store");
  unfinalized.finalize = false;
  build::convert(unfinalized);
  std::filesystem::copy_file(dir_ / "other-store" / format::step_file_name(0),
                             dir_ / "third-store" / format::step_file_name(0),
                             std::filesystem::copy_options::overwrite_existing);
  const auto third = Store::open(dir_ / "third-store", StoreOpenOptions{.allow_incomplete = true});
  expect_error([&] { third->index(0, 0); }, ErrorCode::kCorrupt, {"store_id"});
}

TEST_F(StoreCorruptionTest, CleanStoreVerifies) {
  const VerifyReport report = verify_store(store_path());
  EXPECT_TRUE(report.ok()) << (report.problems.empty() ? "" : report.problems[0]);
  EXPECT_EQ(report.steps_checked, 2u);
  EXPECT_GT(report.bricks_checked, 100u);
}

}  // namespace
}  // namespace strielad
