// SPDX-License-Identifier: Apache-2.0
#include "store/brick_cache.h"

#include <gtest/gtest.h>

namespace strielad {
namespace {

Brick brick_of_bytes(std::size_t n) {
  Brick b;
  b.kind = format::BrickKind::kData;
  b.bytes.resize(n);
  return b;
}

TEST(BrickCacheTest, CountsHitsAndMisses) {
  BrickCache cache(1 << 20, 1);
  int loads = 0;
  const BrickKey key{nullptr, 0, 0, 5};
  cache.get_or_load(key, [&] { ++loads; return brick_of_bytes(100); });
  cache.get_or_load(key, [&] { ++loads; return brick_of_bytes(100); });
  EXPECT_EQ(loads, 1);
  const auto s = cache.stats();
  EXPECT_EQ(s.hits, 1u);
  EXPECT_EQ(s.misses, 1u);
  EXPECT_DOUBLE_EQ(s.hit_rate(), 0.5);
}

TEST(BrickCacheTest, StaysWithinBudgetAndEvictsLeastRecentlyUsed) {
  const std::size_t one = brick_of_bytes(1000).memory_bytes();
  BrickCache cache(3 * one, 1);
  for (NodeId n = 0; n < 3; ++n) cache.get_or_load({nullptr, 0, 0, n}, [] { return brick_of_bytes(1000); });
  cache.find({nullptr, 0, 0, 0});  // 0 becomes the newest
  cache.get_or_load({nullptr, 0, 0, 3}, [] { return brick_of_bytes(1000); });
  EXPECT_TRUE(cache.contains({nullptr, 0, 0, 0}));
  EXPECT_FALSE(cache.contains({nullptr, 0, 0, 1}));  // the least recently used
  EXPECT_LE(cache.stats().bytes, cache.stats().budget);
  EXPECT_EQ(cache.stats().evictions, 1u);
}

TEST(BrickCacheTest, BrickLargerThanTheBudgetIsReturnedButNotKept) {
  BrickCache cache(500, 1);
  const auto b = cache.get_or_load({nullptr, 0, 0, 1}, [] { return brick_of_bytes(10000); });
  EXPECT_EQ(b->bytes.size(), 10000u);
  EXPECT_EQ(cache.stats().entries, 0u);
}

TEST(BrickCacheTest, LoadErrorsPropagateAndCacheNothing) {
  BrickCache cache(1 << 20);
  EXPECT_THROW(cache.get_or_load({nullptr, 0, 0, 1},
                                 []() -> Brick { throw Error(ErrorCode::kCorrupt, "bad"); }),
               Error);
  EXPECT_FALSE(cache.contains({nullptr, 0, 0, 1}));
}

}  // namespace
}  // namespace strielad
