// SPDX-License-Identifier: Apache-2.0
// The report's arrival curves from raw arrival times: pooled over rounds as the mean of
// each round's curve, rising, ending at 100 % only when every round answered its whole
// cut, thinned to the asked number of points; and long chart titles wrap instead of
// being cut off.
#include <gtest/gtest.h>

#include "bench/report_charts.h"
#include "bench/report_plots.h"

namespace strielad::testing {
namespace {

TEST(ReportChartsTest, ArrivalCurveIsTheMeanOfTheRounds) {
  // Round 1 answers its 2 nodes at 1 and 3 s, round 2 its 2 nodes at 2 and 4 s.
  const auto c = bench::pooled_arrival_curve({{1, 3}, {2, 4}}, {2, 2});
  ASSERT_EQ(c.seconds.size(), 4u);
  EXPECT_EQ(c.seconds, (std::vector<double>{1, 2, 3, 4}));
  EXPECT_EQ(c.percent, (std::vector<double>{25, 50, 75, 100}));
}

TEST(ReportChartsTest, ArrivalCurveStopsShortOfAllWhenACutIsIncomplete) {
  const auto c = bench::pooled_arrival_curve({{0.5}}, {4});
  ASSERT_EQ(c.percent.size(), 1u);
  EXPECT_EQ(c.percent.back(), 25);
}

TEST(ReportChartsTest, ArrivalCurveIsThinnedAndRises) {
  std::vector<double> times;
  for (int i = 999; i >= 0; --i) times.push_back(i * 0.001);
  const auto c = bench::pooled_arrival_curve({times}, {1000}, 50);
  ASSERT_EQ(c.seconds.size(), 50u);
  EXPECT_EQ(c.seconds.front(), 0);
  EXPECT_DOUBLE_EQ(c.seconds.back(), 0.999);
  EXPECT_EQ(c.percent.back(), 100);
  for (std::size_t i = 1; i < c.seconds.size(); ++i) {
    EXPECT_GT(c.seconds[i], c.seconds[i - 1]);
    EXPECT_GT(c.percent[i], c.percent[i - 1]);
  }
  EXPECT_TRUE(bench::pooled_arrival_curve({}, {}).seconds.empty());
}

TEST(ReportChartsTest, LongTitlesWrapAtSpaces) {
  EXPECT_EQ(bench::wrap_title("Extraction of cloud fields", 12), "Extraction\nof cloud\nfields");
  EXPECT_EQ(bench::wrap_title("short", 40), "short");
  EXPECT_EQ(bench::wrap_title("averyveryverylongword x", 5), "averyveryverylongword\nx");
}

}  // namespace
}  // namespace strielad::testing
