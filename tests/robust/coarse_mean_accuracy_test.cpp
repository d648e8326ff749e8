// SPDX-License-Identifier: Apache-2.0
// The converter's coarse-level sub-sampling (build/level_sampler.h) against the
// high-precision reference (robust/case_reference.h) on random data spanning 1e-45 to
// 3e38 (float32) and 1e-300 to 1.7e308 (float64) with a quarter of the samples missing:
// centre samples bit for bit, fallback means within the documented bound
// (docs/robustness.md, "Sums and means").
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>

#include "convert/level_sampler.h"
#include "robust/case_reference.h"

namespace strielad::robust {
namespace {

template <typename T>
std::vector<T> random_extremes(std::size_t n, double max_exponent, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> exponent(-max_exponent, max_exponent), unit(0, 1);
  std::vector<T> v(n);
  for (auto& x : v) {
    if (unit(random) < 0.25) {
      x = std::numeric_limits<T>::quiet_NaN();
      continue;
    }
    const double sign = unit(random) < 0.5 ? -1.0 : 1.0;
    const double magnitude = std::pow(10.0, exponent(random));
    x = static_cast<T>(std::clamp(sign * magnitude, -double(std::numeric_limits<T>::max()),
                                  double(std::numeric_limits<T>::max())));
  }
  return v;
}

template <typename T>
void expect_within_bound(double max_exponent, std::uint64_t seed) {
  const OctreeLayout layout(Dims3{33, 17, 9}, 4);
  const auto& f = layout.level(0).samples;
  const auto& c = layout.level(1).samples;
  const std::vector<T> fine = random_extremes<T>(f[0] * f[1] * f[2], max_exponent, seed);
  std::array<bool, 3> halved{};
  for (int a = 0; a < 3; ++a) halved[a] = layout.level(1).stride[a] != layout.level(0).stride[a];
  std::vector<T> coarse(c[0] * c[1] * c[2]);
  build::downsample_planes(build::PlaneBlock<T>{fine.data(), f, 0, f[2]}, halved, coarse, c, 0, c[2]);

  const std::vector<double> fine_d(fine.begin(), fine.end());
  const CoarseReference ref = reference_downsample(layout, 0, fine_d, sizeof(T) == 8);
  std::size_t means = 0;
  for (std::size_t i = 0; i < coarse.size(); ++i) {
    const double got = coarse[i];
    ASSERT_EQ(std::isnan(got), std::isnan(ref.values[i])) << "sample " << i;
    if (std::isnan(got)) continue;
    ASSERT_TRUE(std::isfinite(got)) << "sample " << i;
    if (!ref.fallback[i]) {
      ASSERT_EQ(std::bit_cast<std::uint64_t>(got), std::bit_cast<std::uint64_t>(ref.values[i]));
      continue;
    }
    ++means;
    const long double error = std::fabs(static_cast<long double>(got) - ref.exact[i]);
    ASSERT_LE(error, ref.tolerance[i]) << "sample " << i << ": " << got << " against exact "
                                       << static_cast<double>(ref.exact[i]);
  }
  EXPECT_GT(means, 50u);
}

TEST(CoarseMeanAccuracyTest, Float32AcrossTheWholeRange) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) expect_within_bound<float>(38, seed);
}

TEST(CoarseMeanAccuracyTest, Float64AcrossTheWholeRange) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) expect_within_bound<double>(308, seed);
}

TEST(CoarseMeanAccuracyTest, CancellationIsWithinTheBoundNotExact) {
  // 1e30 - 1e30 + 1: the double sum loses the 1 (1e30 + 1 == 1e30), the bound allows it.
  const float kNaN = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> fine = {1e30f, kNaN, -1e30f};
  std::vector<float> coarse(2);
  build::downsample_planes(build::PlaneBlock<float>{fine.data(), {3, 1, 1}, 0, 1},
                           {true, false, false}, coarse, {2, 1, 1}, 0, 1);
  EXPECT_EQ(coarse[0], 1e30f);  // a valid centre is taken as is
  const std::vector<float> gap = {1e30f, 1.0f, kNaN, -1e30f, 5.0f};
  std::vector<float> c3(3);
  build::downsample_planes(build::PlaneBlock<float>{gap.data(), {5, 1, 1}, 0, 1},
                           {true, false, false}, c3, {3, 1, 1}, 0, 1);
  const long double exact = (1.0L + -1e30L) / 2;  // neighbours of the fill: 1 and -1e30
  const double bound = mean_tolerance(exact, 1.0L + 1e30L, 2, false);
  EXPECT_LE(std::fabs(static_cast<long double>(c3[1]) - exact), bound);
}

TEST(CoarseMeanAccuracyTest, BoundIsHalfAnUlpWithoutCancellation) {
  // Means of same-signed floats: the double accumulation adds far less than half a
  // float ulp, so the bound is about half an ulp of the result.
  const double bound = mean_tolerance(1.0L, 2.0L, 2, false);
  EXPECT_GT(bound, std::ldexp(1.0, -24));  // half of float's 2^-23 spacing above 1
  EXPECT_LT(bound, std::ldexp(1.0, -24) * 1.001);
}

}  // namespace
}  // namespace strielad::robust
