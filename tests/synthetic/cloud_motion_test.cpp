// SPDX-License-Identifier: Apache-2.0
// Clouds drift with the mean (westerly) wind from one time step to the next.
#include <gtest/gtest.h>

#include <cmath>

#include "sample_test_util.h"

namespace strielad::testing {
namespace {

// Mismatch between level b and level a shifted east by `shift` cells.
double cloud_mismatch(const std::vector<float>& a, const std::vector<float>& b, std::size_t nx,
                std::size_t ny, long shift) {
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 20; i + 20 < nx; ++i) {
      const long src = static_cast<long>(i) - shift;
      const bool ca = a[j * nx + static_cast<std::size_t>(src)] > 0, cb = b[j * nx + i] > 0;
      sum += ca != cb;
      ++n;
    }
  }
  return sum / static_cast<double>(n);
}

TEST(SampleCloudMotionTest, CloudsMoveEastBetweenSteps) {
  // 240 columns over ~700 km: 2.9 km per cell; 30 min at ~7 m/s is ~4 cells.
  auto spec = small_spec(Dims3{240, 120, 40}, 2);
  spec.variables = {"clw"};
  spec.step_seconds = 1800;
  const GeneratedSample s(spec);
  ASSERT_EQ(s.result.files.size(), 2u);
  const NcFile f0(s.file(0)), f1(s.file(1));
  const auto height = f0.doubles("height");
  // The level closest to 2.2 km, where liquid clouds are most frequent.
  std::size_t k = 0;
  for (std::size_t i = 0; i < height.size(); ++i) {
    if (std::abs(height[i] - 2200) < std::abs(height[k] - 2200)) k = i;
  }
  const auto a = f0.level("clw", 0, k), b = f1.level("clw", 0, k);
  ASSERT_GT(nonzero_fraction(a), 0.02);
  ASSERT_GT(nonzero_fraction(b), 0.02);
  EXPECT_NE(a, b);

  long best_shift = 0;
  double best = 1e9;
  for (long shift = -10; shift <= 10; ++shift) {
    const double m = cloud_mismatch(a, b, 240, 120, shift);
    if (m < best) {
      best = m;
      best_shift = shift;
    }
  }
  EXPECT_GE(best_shift, 2) << "clouds should drift east by a few cells";
  EXPECT_LE(best_shift, 7);
  EXPECT_LT(best, cloud_mismatch(a, b, 240, 120, 0)) << "the shifted field matches better";
}

TEST(SampleCloudMotionTest, TimeCoordinateAdvancesByStepSeconds) {
  auto spec = small_spec(Dims3{8, 8, 8}, 3);
  spec.variables = {"clw"};
  spec.step_seconds = 600;
  const GeneratedSample s(spec);
  for (std::size_t t = 0; t < 3; ++t) {
    const NcFile f(s.file(t));
    EXPECT_EQ(f.doubles("time"), std::vector<double>{600.0 * static_cast<double>(t)});
  }
}

}  // namespace
}  // namespace strielad::testing
