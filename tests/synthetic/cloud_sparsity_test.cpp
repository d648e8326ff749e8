// SPDX-License-Identifier: Apache-2.0
// Cloud liquid, cloud ice and rain are sparse like model output: mostly exactly zero,
// a few percent of cloud, realistic magnitudes, and each only at its own heights.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ostream>

#include "sample_test_util.h"

namespace strielad::testing {
namespace {

struct SparseCase {
  const char* name;
  double min_height, max_height;  // m: nonzero only strictly inside
  float min_peak, max_peak;       // kg/kg: the largest value lies in between
};

void PrintTo(const SparseCase& c, std::ostream* os) { *os << c.name; }

class SampleCloudSparsityTest : public ::testing::TestWithParam<SparseCase> {
 protected:
  static void SetUpTestSuite() {
    auto spec = small_spec(Dims3{96, 104, 60});
    spec.variables = {"clw", "cli", "qr"};
    sample_ = new GeneratedSample(spec);
  }
  static void TearDownTestSuite() {
    delete sample_;
    sample_ = nullptr;
  }
  static GeneratedSample* sample_;
};
GeneratedSample* SampleCloudSparsityTest::sample_ = nullptr;

TEST_P(SampleCloudSparsityTest, MostlyExactZerosWithAFewPercentOfCloud) {
  const SparseCase& c = GetParam();
  const NcFile f(sample_->file());
  const auto values = f.floats(c.name);
  const double fraction = nonzero_fraction(values);
  EXPECT_GT(fraction, 0.01) << c.name;
  EXPECT_LT(fraction, 0.12) << c.name;
  float peak = 0;
  for (const float v : values) {
    ASSERT_TRUE(std::isfinite(v)) << c.name;
    ASSERT_GE(v, 0.0f) << c.name;
    peak = std::max(peak, v);
  }
  EXPECT_GT(peak, c.min_peak) << c.name;
  EXPECT_LT(peak, c.max_peak) << c.name;
}

TEST_P(SampleCloudSparsityTest, NonzeroOnlyAtItsHeights) {
  const SparseCase& c = GetParam();
  const NcFile f(sample_->file());
  const auto height = f.doubles("height");
  std::size_t levels_with_cloud = 0;
  for (std::size_t k = 0; k < height.size(); ++k) {
    const double fraction = nonzero_fraction(f.level(c.name, 0, k));
    if (height[k] <= c.min_height || height[k] >= c.max_height) {
      EXPECT_EQ(fraction, 0.0) << c.name << " at " << height[k] << " m";
    }
    levels_with_cloud += fraction > 0;
  }
  EXPECT_GE(levels_with_cloud, 3u) << c.name;
}

INSTANTIATE_TEST_SUITE_P(
    Species, SampleCloudSparsityTest,
    ::testing::Values(SparseCase{"clw", 500, 6000, 3e-4f, 1.5e-3f},
                      SparseCase{"cli", 6000, 12000, 3e-5f, 2e-4f},
                      SparseCase{"qr", 0, 3500, 1e-4f, 8e-4f}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(SampleCloudPlacementTest, RainFallsUnderLiquidClouds) {
  auto spec = small_spec(Dims3{96, 104, 60});
  spec.variables = {"clw", "qr"};
  const GeneratedSample s(spec);
  const NcFile f(s.file());
  const auto height = f.doubles("height");
  const std::size_t n = 96 * 104;
  // Columns with rain near the ground must have liquid cloud somewhere above.
  std::vector<bool> cloudy(n, false);
  std::size_t lowest = height.size() - 1;
  for (std::size_t k = 0; k < height.size(); ++k) {
    if (height[k] < 500) continue;
    const auto clw = f.level("clw", 0, k);
    for (std::size_t i = 0; i < n; ++i) cloudy[i] = cloudy[i] || clw[i] > 0;
  }
  const auto rain = f.level("qr", 0, lowest);
  std::size_t rainy = 0, rainy_under_cloud = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (rain[i] > 0) {
      ++rainy;
      rainy_under_cloud += cloudy[i];
    }
  }
  ASSERT_GT(rainy, 0u);
  EXPECT_GT(static_cast<double>(rainy_under_cloud) / static_cast<double>(rainy), 0.8);
}

}  // namespace
}  // namespace strielad::testing
