// SPDX-License-Identifier: Apache-2.0
// Percentiles interpolate between closest ranks (numpy's default) and summaries of
// unsorted input are order-independent.
#include <gtest/gtest.h>

#include <vector>

#include "bench/latency_stats.h"
#include "bench/table_writer.h"
#include "core/error.h"

namespace strielad {
namespace {

TEST(LatencyStats, PercentilesInterpolateBetweenRanks) {
  const std::vector<double> sorted = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  EXPECT_DOUBLE_EQ(bench::percentile_sorted(sorted, 0.0), 1);
  EXPECT_DOUBLE_EQ(bench::percentile_sorted(sorted, 0.5), 5.5);
  EXPECT_DOUBLE_EQ(bench::percentile_sorted(sorted, 0.99), 9.91);
  EXPECT_DOUBLE_EQ(bench::percentile_sorted(sorted, 1.0), 10);
  EXPECT_DOUBLE_EQ(bench::median({3, 1, 2}), 2);
  EXPECT_DOUBLE_EQ(bench::median({}), 0);
}

TEST(LatencyStats, SummaryOfUnsortedValues) {
  const bench::Summary s = bench::summarize({9, 1, 5, 3, 7});
  EXPECT_EQ(s.count, 5u);
  EXPECT_DOUBLE_EQ(s.min, 1);
  EXPECT_DOUBLE_EQ(s.max, 9);
  EXPECT_DOUBLE_EQ(s.p50, 5);
  EXPECT_DOUBLE_EQ(s.mean, 5);
  EXPECT_LE(s.p90, s.p99);
  EXPECT_EQ(bench::summarize({}).count, 0u);
}

TEST(TableWriter, RejectsRowsOfTheWrongWidth) {
  bench::Table t{"t", "T", {"a", "b"}, {}, {}};
  t.add({"x", bench::Cell(1.5, 1)});
  EXPECT_THROW(t.add({"only one"}), Error);
  EXPECT_EQ(t.rows.front()[1].display(), "1.5");
  EXPECT_EQ(t.rows.front()[1].exact(), "1.5");
}

}  // namespace
}  // namespace strielad
