// SPDX-License-Identifier: Apache-2.0
// A conversion that stops part-way leaves no file a reader accepts, and re-running the
// same command converts only the missing time steps.
#include <gtest/gtest.h>

#include <fstream>

#include "convert/converter.h"
#include "support/expect_error.h"
#include "store/store.h"
#include "support/small_dataset.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using testing::expect_error;

TEST(InterruptedConversionResumesTest, RerunConvertsOnlyMissingSteps) {
  testing::TempDir dir;
  const auto data = testing::write_small_dataset(dir.path(), 23, 17, 11, 3);
  auto partial = testing::small_convert_options(data, dir / "store");
  partial.only_first = 0;
  partial.only_last = 0;
  const auto first = build::convert(partial);
  EXPECT_EQ(first.steps_converted, 1u);
  EXPECT_FALSE(first.finalized);

  // A killed writer leaves only a temporary sibling; readers and resume ignore it.
  { std::ofstream(dir / "store/steps/step-000001.bricks.tmp.99999") << "half-written"; }
  expect_error([&] { Store::open(dir / "store"); }, ErrorCode::kInvalidArgument,
               {"not been finalized"});
  const auto incomplete = Store::open(dir / "store", StoreOpenOptions{.allow_incomplete = true});
  EXPECT_TRUE(incomplete->has_step(0));
  EXPECT_FALSE(incomplete->has_step(1));
  expect_error([&] { incomplete->index(1, 0); }, ErrorCode::kNotFound, {"time step 1 not converted"});

  const auto second = build::convert(testing::small_convert_options(data, dir / "store"));
  EXPECT_EQ(second.steps_skipped, 1u);
  EXPECT_EQ(second.steps_converted, 2u);
  EXPECT_TRUE(second.finalized);
  EXPECT_FALSE(std::filesystem::exists(dir / "store/steps/step-000001.bricks.tmp.99999"));
  const auto store = Store::open(dir / "store");
  EXPECT_TRUE(store->manifest().complete);
  EXPECT_NO_THROW(store->read_brick(2, 0, store->octree().root()));

  const auto third = build::convert(testing::small_convert_options(data, dir / "store"));
  EXPECT_EQ(third.steps_converted, 0u);
}

TEST(InterruptedConversionResumesTest, DamagedStepFileIsConvertedAgain) {
  testing::TempDir dir;
  const auto data = testing::write_small_dataset(dir.path(), 23, 17, 11, 2);
  auto opts = testing::small_convert_options(data, dir / "store");
  opts.finalize = false;
  build::convert(opts);
  const auto step1 = dir / "store/steps/step-000001.bricks";
  std::filesystem::resize_file(step1, std::filesystem::file_size(step1) / 2);
  const auto r = build::convert(testing::small_convert_options(data, dir / "store"));
  EXPECT_EQ(r.steps_skipped, 1u);
  EXPECT_EQ(r.steps_converted, 1u);
  EXPECT_TRUE(r.finalized);
}

TEST(InterruptedConversionResumesTest, DifferentOptionsRefuseToMixIntoAnExistingStore) {
  testing::TempDir dir;
  const auto data = testing::write_small_dataset(dir.path(), 23, 17, 11, 1);
  build::convert(testing::small_convert_options(data, dir / "store"));
  auto other = testing::small_convert_options(data, dir / "store", 8);
  expect_error([&] { build::convert(other); }, ErrorCode::kAlreadyExists,
               {"different inputs or options", "octree"});
}

}  // namespace
}  // namespace strielad
