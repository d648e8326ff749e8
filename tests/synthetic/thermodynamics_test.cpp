// SPDX-License-Identifier: Apache-2.0
// Temperature follows the standard atmosphere with plausible horizontal variation, and
// pressure is hydrostatic: it falls with height in every column, consistently with ta.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "sample_test_util.h"

namespace strielad::testing {
namespace {

constexpr double kGravity = 9.80665, kGasConstant = 287.053;

class SampleThermodynamicsTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    auto spec = small_spec(Dims3{40, 44, 50});
    spec.variables = {"ta", "pres"};
    sample_ = new GeneratedSample(spec);
  }
  static void TearDownTestSuite() {
    delete sample_;
    sample_ = nullptr;
  }
  static double mean(const std::vector<float>& v) {
    double s = 0;
    for (const float x : v) s += x;
    return s / static_cast<double>(v.size());
  }
  static GeneratedSample* sample_;
};
GeneratedSample* SampleThermodynamicsTest::sample_ = nullptr;

TEST_F(SampleThermodynamicsTest, TemperatureFallsThroughTheTroposphereAndLevelsOffAbove) {
  const NcFile f(sample_->file());
  const auto height = f.doubles("height");  // top to bottom
  double previous = 0;
  for (std::size_t k = height.size(); k-- > 0;) {  // bottom to top
    const auto ta = f.level("ta", 0, k);
    for (const float t : ta) {
      ASSERT_GT(t, 195.0f) << height[k];
      ASSERT_LT(t, 315.0f) << height[k];
    }
    const double m = mean(ta);
    if (k + 1 < height.size() && height[k] < 10500) {
      EXPECT_LT(m, previous) << "level mean must fall with height at " << height[k] << " m";
    }
    if (height[k] < 100) {
      EXPECT_NEAR(m, 288.0, 6.0) << "near the ground";
    }
    if (height[k] > 12000) {
      EXPECT_NEAR(m, 216.65, 4.0) << "isothermal stratosphere at " << height[k] << " m";
    }
    previous = m;
  }
}

TEST_F(SampleThermodynamicsTest, TemperatureVariesHorizontally) {
  const NcFile f(sample_->file());
  const auto ta = f.level("ta", 0, f.dim_length("height") - 1);
  const auto [lo, hi] = std::minmax_element(ta.begin(), ta.end());
  EXPECT_GT(*hi - *lo, 1.0f);
  EXPECT_LT(*hi - *lo, 20.0f);
}

TEST_F(SampleThermodynamicsTest, PressureFallsWithHeightInEveryColumn) {
  const NcFile f(sample_->file());
  const auto height = f.doubles("height");
  const std::size_t nz = height.size();
  const auto ground = f.level("pres", 0, nz - 1);
  for (const float p : ground) {
    EXPECT_GT(p, 96000.0f);
    EXPECT_LT(p, 104000.0f);
  }
  std::vector<float> below = ground;
  for (std::size_t k = nz - 1; k-- > 0;) {
    const auto p = f.level("pres", 0, k);
    for (std::size_t i = 0; i < p.size(); ++i) ASSERT_LT(p[i], below[i]) << height[k];
    below = p;
  }
  for (const float p : f.level("pres", 0, 0)) {  // ~21 km
    EXPECT_GT(p, 2000.0f);
    EXPECT_LT(p, 8000.0f);
  }
}

TEST_F(SampleThermodynamicsTest, PressureIsHydrostaticWithTheTemperature) {
  // ln(p_lower / p_upper) = g dz / (R T_mean) for every layer, within 1 %.
  const NcFile f(sample_->file());
  const auto height = f.doubles("height");
  for (std::size_t k = 0; k + 1 < height.size(); ++k) {
    const auto pu = f.level("pres", 0, k), pl = f.level("pres", 0, k + 1);
    const auto tu = f.level("ta", 0, k), tl = f.level("ta", 0, k + 1);
    const double dz = height[k] - height[k + 1];
    for (std::size_t i = 0; i < pu.size(); i += 7) {
      const double t_mean = 0.5 * (tu[i] + tl[i]);
      const double expected = kGravity * dz / (kGasConstant * t_mean);
      const double actual = std::log(static_cast<double>(pl[i]) / pu[i]);
      ASSERT_NEAR(actual, expected, 0.01 * expected + 1e-5) << "layer " << k << " column " << i;
    }
  }
}

}  // namespace
}  // namespace strielad::testing
