// SPDX-License-Identifier: Apache-2.0
// Axes: height is stretched and stored top to bottom like ICON; lon/lat are uniform,
// ascending and cover the SciVis domain over Germany.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "synthetic/sample_grid.h"
#include "sample_test_util.h"

namespace strielad::testing {
namespace {

TEST(SampleHeightAxisTest, FullGridHeightsDescendFromTopToNearGround) {
  const auto z = synthetic::stretched_heights(150);
  ASSERT_EQ(z.size(), 150u);
  EXPECT_NEAR(z.front(), 21000.0, 1e-9);
  EXPECT_NEAR(z.back(), 20.0, 1e-9);
  for (std::size_t k = 0; k + 1 < z.size(); ++k) ASSERT_GT(z[k], z[k + 1]) << k;
}

TEST(SampleHeightAxisTest, SpacingGrowsWithHeight) {
  const auto z = synthetic::stretched_heights(150);
  for (std::size_t k = 0; k + 2 < z.size(); ++k) {
    ASSERT_GT(z[k] - z[k + 1], z[k + 1] - z[k + 2]) << "level " << k;
  }
  EXPECT_LT(z[148] - z[149], 40.0) << "fine near the ground";
  EXPECT_GT(z[0] - z[1], 300.0) << "coarse near the top";
  // Roughly half of the levels lie in the lowest 5 km, as in ICON-LEM.
  const auto low = std::count_if(z.begin(), z.end(), [](double h) { return h < 5000; });
  EXPECT_GT(low, 60);
  EXPECT_LT(low, 110);
}

TEST(SampleHeightAxisTest, FileHeightAxisIsDescendingAndStretched) {
  auto spec = small_spec(Dims3{3, 3, 12});
  spec.variables = {"ta"};
  const GeneratedSample s(spec);
  const NcFile f(s.file());
  const auto z = f.doubles("height");
  ASSERT_EQ(z.size(), 12u);
  EXPECT_EQ(z, synthetic::stretched_heights(12));
  for (std::size_t k = 0; k + 2 < z.size(); ++k) {
    EXPECT_GT(z[k], z[k + 1]);
    EXPECT_GT(z[k] - z[k + 1], z[k + 1] - z[k + 2]);
  }
  EXPECT_EQ(f.text_att("height", "positive"), "up");
}

TEST(SampleHeightAxisTest, LonLatAreUniformAndAscendingOverGermany) {
  auto spec = small_spec(Dims3{11, 8, 2});
  spec.variables = {"ta"};
  const GeneratedSample s(spec);
  const NcFile f(s.file());
  const auto lon = f.doubles("lon"), lat = f.doubles("lat");
  ASSERT_EQ(lon.size(), 11u);
  ASSERT_EQ(lat.size(), 8u);
  EXPECT_DOUBLE_EQ(lon.front(), 4.5);
  EXPECT_DOUBLE_EQ(lon.back(), 14.5);
  EXPECT_DOUBLE_EQ(lat.front(), 47.5);
  EXPECT_DOUBLE_EQ(lat.back(), 54.5);
  for (std::size_t i = 0; i + 1 < lon.size(); ++i) EXPECT_NEAR(lon[i + 1] - lon[i], 1.0, 1e-12);
  for (std::size_t j = 0; j + 1 < lat.size(); ++j) EXPECT_NEAR(lat[j + 1] - lat[j], 1.0, 1e-12);
}

}  // namespace
}  // namespace strielad::testing
