// SPDX-License-Identifier: Apache-2.0
// Coarse levels are sub-sampled ignoring fill: a fill sample at a sub-sampling position
// is replaced by the mean of its valid neighbours; all-fill regions stay missing.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "convert/level_sampler.h"

namespace strielad::build {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

TEST(CoarseLevelsIgnoreFillTest, ValidCentreIsTakenAsIs) {
  // 5 x 1 x 1 fine samples, x halved: coarse samples at fine 0, 2, 4.
  const std::vector<float> fine = {1, 2, 3, 4, 5};
  std::vector<float> coarse(3);
  downsample_planes(PlaneBlock<float>{fine.data(), {5, 1, 1}, 0, 1}, {true, false, false}, coarse,
                    {3, 1, 1}, 0, 1);
  EXPECT_EQ(coarse, (std::vector<float>{1, 3, 5}));
}

TEST(CoarseLevelsIgnoreFillTest, FillCentreBecomesMeanOfValidNeighbours) {
  const std::vector<float> fine = {1, 2, kNaN, 6, 5};
  std::vector<float> coarse(3);
  downsample_planes(PlaneBlock<float>{fine.data(), {5, 1, 1}, 0, 1}, {true, false, false}, coarse,
                    {3, 1, 1}, 0, 1);
  EXPECT_EQ(coarse[1], 4.0f);  // mean of 2 and 6, the NaN ignored
}

TEST(CoarseLevelsIgnoreFillTest, AllFillNeighbourhoodStaysMissing) {
  const std::vector<float> fine = {1, kNaN, kNaN, kNaN, 5};
  std::vector<float> coarse(3);
  downsample_planes(PlaneBlock<float>{fine.data(), {5, 1, 1}, 0, 1}, {true, false, false}, coarse,
                    {3, 1, 1}, 0, 1);
  EXPECT_TRUE(std::isnan(coarse[1]));
}

TEST(CoarseLevelsIgnoreFillTest, LastSampleIsAlwaysKept) {
  // 6 fine samples: coarse has ceil(5/2)+1 = 4 samples at fine 0, 2, 4, 5.
  const std::vector<float> fine = {0, 1, 2, 3, 4, 5};
  std::vector<float> coarse(4);
  downsample_planes(PlaneBlock<float>{fine.data(), {6, 1, 1}, 0, 1}, {true, false, false}, coarse,
                    {4, 1, 1}, 0, 1);
  EXPECT_EQ(coarse, (std::vector<float>{0, 2, 4, 5}));
}

TEST(CoarseLevelsIgnoreFillTest, MeanIsComputedInDoubleForExtremeValues) {
  // In float, 3e38 + 3e38 overflows to Inf; the double mean stays finite.
  const std::vector<float> fine = {3e38f, kNaN, 3e38f};
  std::vector<float> coarse(2);
  downsample_planes(PlaneBlock<float>{fine.data(), {3, 1, 1}, 0, 1}, {true, false, false}, coarse,
                    {2, 1, 1}, 0, 1);
  EXPECT_EQ(coarse[0], 3e38f);
  const std::vector<float> gap = {3e38f, 3e38f, kNaN, 3e38f, 3e38f};
  std::vector<float> c2(3);
  downsample_planes(PlaneBlock<float>{gap.data(), {5, 1, 1}, 0, 1}, {true, false, false}, c2,
                    {3, 1, 1}, 0, 1);
  EXPECT_EQ(c2[1], 3e38f);
}

TEST(CoarseLevelsIgnoreFillTest, MeanOfFloat64NearItsMaximumDoesNotOverflow) {
  // 1.5e308 + 1.7e308 overflows a double: the mean used to be stored as Inf.
  constexpr double kDNaN = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> fine = {1.5e308, 1.7e308, kDNaN, 1.6e308, 1.7e308};
  std::vector<double> coarse(3);
  downsample_planes(PlaneBlock<double>{fine.data(), {5, 1, 1}, 0, 1}, {true, false, false}, coarse,
                    {3, 1, 1}, 0, 1);
  EXPECT_EQ(coarse[0], 1.5e308);
  EXPECT_DOUBLE_EQ(coarse[1], (1.7e308 / 2 + 1.6e308 / 2));
  EXPECT_TRUE(std::isfinite(coarse[1]));
  // Means that do not overflow are computed as before (bit for bit).
  const std::vector<double> small = {1.0, 0.1, kDNaN, 0.2, 5.0};
  downsample_planes(PlaneBlock<double>{small.data(), {5, 1, 1}, 0, 1}, {true, false, false}, coarse,
                    {3, 1, 1}, 0, 1);
  EXPECT_EQ(coarse[1], (0.1 + 0.2) / 2.0);
}

TEST(CoarseLevelsIgnoreFillTest, UnhalvedAxisIsCopied) {
  // 3 x 2 planes, only x halved: y is kept as is.
  const std::vector<float> fine = {1, 2, 3, 4, kNaN, 6};
  std::vector<float> coarse(4);
  downsample_planes(PlaneBlock<float>{fine.data(), {3, 2, 1}, 0, 1}, {true, false, false}, coarse,
                    {2, 2, 1}, 0, 1);
  EXPECT_EQ(coarse, (std::vector<float>{1, 3, 4, 6}));
}

}  // namespace
}  // namespace strielad::build
