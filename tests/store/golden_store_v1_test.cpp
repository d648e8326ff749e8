// SPDX-License-Identifier: Apache-2.0
// A store written by version 0.1.0 (format version 1) and checked in: every later reader
// must open it and read the same values. Made with
//   strielad-convert sample -o nc --dims 9x7x5 --steps 2 --vars clw,ta
//   strielad-convert nc/*.nc -o golden-store-v1 --brick 4
#include <gtest/gtest.h>

#include "store/store.h"
#include "store/store_verifier.h"

namespace strielad {
namespace {

const std::filesystem::path kGolden =
    std::filesystem::path(STRIELAD_SOURCE_DIR) / "tests/data/golden-store-v1";

TEST(GoldenStoreV1Test, OpensAndVerifies) {
  const auto store = Store::open(kGolden);
  const auto& m = store->manifest();
  EXPECT_EQ(m.store_id, 0x9492072abaf11c7aull);
  EXPECT_EQ(store->octree().node_count(), 5u);
  EXPECT_EQ(m.variables.size(), 2u);
  EXPECT_EQ(m.z.values.front(), 21000.0);
  EXPECT_EQ(m.time.values, (std::vector<double>{0.0, 300.0}));
  const VerifyReport r = verify_store(kGolden);
  EXPECT_TRUE(r.ok()) << (r.problems.empty() ? "" : r.problems.front());
}

TEST(GoldenStoreV1Test, ReadsTheSameValues) {
  const auto store = Store::open(kGolden);
  const auto ta = static_cast<std::uint32_t>(store->manifest().variable_index("ta"));
  const auto& root = store->node_entry(1, ta, store->octree().root());
  EXPECT_EQ(root.valid_count, 9u * 7u * 5u);
  EXPECT_EQ(root.min, 212.32926940917969);
  EXPECT_EQ(root.max, 291.91290283203125);
  const Brick b = store->read_brick(1, ta, 0);
  EXPECT_EQ(b.kind, format::BrickKind::kData);
  EXPECT_EQ(b.sample(0), 220.13002014160156);
  EXPECT_EQ(b.sample(b.sample_count() - 1), 285.88436889648438);
}

}  // namespace
}  // namespace strielad
