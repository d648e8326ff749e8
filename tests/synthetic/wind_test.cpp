// SPDX-License-Identifier: Apache-2.0
// Winds: a westerly jet peaking near 10 km, a cyclonic vortex at the surface pressure
// low, and a small vertical wind with stronger updrafts in clouds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sample_test_util.h"

namespace strielad::testing {
namespace {

class SampleWindTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    auto spec = small_spec(Dims3{64, 70, 50});
    spec.variables = {"ua", "va", "wa", "clw", "pres"};
    sample_ = new GeneratedSample(spec);
  }
  static void TearDownTestSuite() {
    delete sample_;
    sample_ = nullptr;
  }
  static GeneratedSample* sample_;
};
GeneratedSample* SampleWindTest::sample_ = nullptr;

TEST_F(SampleWindTest, WesterlyJetPeaksNearTenKilometres) {
  const NcFile f(sample_->file());
  const auto height = f.doubles("height");
  double best = -1e9, best_height = 0, ground_mean = 0;
  for (std::size_t k = 0; k < height.size(); ++k) {
    const auto ua = f.level("ua", 0, k);
    double s = 0;
    for (const float u : ua) {
      ASSERT_TRUE(std::isfinite(u));
      ASSERT_LT(std::abs(u), 80.0f);
      s += u;
    }
    const double m = s / static_cast<double>(ua.size());
    if (m > best) {
      best = m;
      best_height = height[k];
    }
    if (k + 1 == height.size()) ground_mean = m;
  }
  EXPECT_GT(best_height, 8000.0);
  EXPECT_LT(best_height, 12500.0);
  EXPECT_GT(best, 20.0);
  EXPECT_LT(best, 45.0);
  EXPECT_GT(ground_mean, 0.0);
  EXPECT_LT(ground_mean, 10.0);
}

TEST_F(SampleWindTest, SurfaceWindCirculatesCounterClockwiseAroundThePressureLow) {
  const NcFile f(sample_->file());
  const std::size_t nz = f.dim_length("height"), nx = 64, ny = 70;
  const auto p = f.level("pres", 0, nz - 1);
  const auto ua = f.level("ua", 0, nz - 1), va = f.level("va", 0, nz - 1);
  const auto low = static_cast<std::size_t>(std::min_element(p.begin(), p.end()) - p.begin());
  const long ci = static_cast<long>(low % nx), cj = static_cast<long>(low / nx);
  // Circulation on a square of half-width r cells around the low (counter-clockwise).
  double circulation = 0;
  int samples = 0;
  for (long r = 3; r <= 8; ++r) {
    for (long d = -r; d <= r; ++d) {
      const auto at = [&](long i, long j) -> long {
        if (i < 0 || j < 0 || i >= static_cast<long>(nx) || j >= static_cast<long>(ny)) return -1;
        return j * static_cast<long>(nx) + i;
      };
      if (long a = at(ci + d, cj - r); a >= 0) circulation += ua[a], ++samples;   // south: +u
      if (long a = at(ci + r, cj + d); a >= 0) circulation += va[a], ++samples;   // east: +v
      if (long a = at(ci + d, cj + r); a >= 0) circulation -= ua[a], ++samples;   // north: -u
      if (long a = at(ci - r, cj + d); a >= 0) circulation -= va[a], ++samples;   // west: -v
    }
  }
  ASSERT_GT(samples, 0);
  EXPECT_GT(circulation / samples, 1.0) << "cyclonic (counter-clockwise) flow around the low";
}

TEST_F(SampleWindTest, VerticalWindIsSmallExceptInClouds) {
  const NcFile f(sample_->file());
  const auto wa = f.floats("wa"), clw = f.floats("clw");
  std::size_t clear = 0, clear_small = 0;
  float cloud_max = 0;
  for (std::size_t i = 0; i < wa.size(); ++i) {
    ASSERT_TRUE(std::isfinite(wa[i]));
    ASSERT_LT(std::abs(wa[i]), 5.0f);
    if (clw[i] > 0) {
      cloud_max = std::max(cloud_max, wa[i]);
    } else {
      ++clear;
      clear_small += std::abs(wa[i]) <= 0.5f;
    }
  }
  EXPECT_GT(static_cast<double>(clear_small) / static_cast<double>(clear), 0.95);
  EXPECT_GT(cloud_max, 1.0f) << "updrafts inside clouds";
}

}  // namespace
}  // namespace strielad::testing
