// SPDX-License-Identifier: Apache-2.0
// Property: a node whose recorded [min, max] misses a value interval has no
// full-resolution sample inside that interval, at every level; statistics are exact at
// level 0 and valid counts add up to the grid's on every level.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "convert/converter.h"
#include "store/store.h"
#include "support/small_dataset.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

TEST(ValueRangeCullingTest, NodeOutOfRangeHasNoSampleInRange) {
  testing::TempDir dir;
  const auto data = testing::write_small_dataset(dir.path(), 37, 29, 15, 1);
  build::convert(testing::small_convert_options(data, dir / "store", 4));
  const auto store = Store::open(dir / "store");
  const auto& layout = store->octree();
  ASSERT_GE(layout.level_count(), 4u);
  const auto var = static_cast<std::uint32_t>(store->manifest().variable_index("cloud"));
  const auto entries = store->index(0, var);

  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1e-4, 6e-4);
  std::size_t culled = 0;
  for (int trial = 0; trial < 200; ++trial) {
    double lo = u(rng), hi = u(rng);
    if (lo > hi) std::swap(lo, hi);
    for (NodeId n = 0; n < layout.node_count(); ++n) {
      const auto& e = entries[n];
      const bool excluded = !e.has_valid_data() || e.max < lo || e.min > hi;
      if (!excluded) continue;
      ++culled;
      const IndexBox box = layout.fine_box(layout.key(n));
      for (std::size_t z = box.lo[2]; z <= box.hi[2]; ++z)
        for (std::size_t y = box.lo[1]; y <= box.hi[1]; ++y)
          for (std::size_t x = box.lo[0]; x <= box.hi[0]; ++x) {
            const double v = testing::small_cloud_value(x, y, z, 0);
            const double stored = std::isnan(v) ? v : double(float(v));
            ASSERT_FALSE(stored >= lo && stored <= hi)
                << "node " << n << " was culled for [" << lo << ", " << hi << "] but sample ("
                << x << "," << y << "," << z << ") = " << stored;
          }
    }
  }
  EXPECT_GT(culled, 1000u);  // the property was exercised
}

TEST(ValueRangeCullingTest, StatisticsAreExactAndCountsAddUpOnEveryLevel) {
  testing::TempDir dir;
  const auto data = testing::write_small_dataset(dir.path(), 37, 29, 15, 1);
  build::convert(testing::small_convert_options(data, dir / "store", 4));
  const auto store = Store::open(dir / "store");
  const auto& layout = store->octree();
  const auto var = static_cast<std::uint32_t>(store->manifest().variable_index("cloud"));
  const auto entries = store->index(0, var);
  std::uint64_t grid_valid = 0;
  double grid_min = INFINITY, grid_max = -INFINITY;
  for (std::size_t z = 0; z < 15; ++z)
    for (std::size_t y = 0; y < 29; ++y)
      for (std::size_t x = 0; x < 37; ++x) {
        const double v = testing::small_cloud_value(x, y, z, 0);
        if (std::isnan(v)) continue;
        ++grid_valid;
        grid_min = std::min(grid_min, double(float(v)));
        grid_max = std::max(grid_max, double(float(v)));
      }
  for (std::size_t l = 0; l < layout.level_count(); ++l) {
    std::uint64_t valid = 0;
    const auto& s = layout.level(l);
    for (NodeId n = s.first_node; n < s.first_node + s.node_count(); ++n) valid += entries[n].valid_count;
    EXPECT_EQ(valid, grid_valid) << "level " << l;
  }
  EXPECT_EQ(entries[layout.root()].min, grid_min);
  EXPECT_EQ(entries[layout.root()].max, grid_max);
}

}  // namespace
}  // namespace strielad
