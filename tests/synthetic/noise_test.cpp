// SPDX-License-Identifier: Apache-2.0
// The integer-hash value noise: bounded, deterministic, smooth, and the row evaluation
// agrees with point evaluation.
#include <gtest/gtest.h>

#include <cmath>

#include "synthetic/hash_noise.h"
#include "synthetic/sample_grid.h"

namespace strielad::synthetic {
namespace {

TEST(SampleNoiseTest, LatticeValuesAreBoundedDeterministicAndVaried) {
  const std::uint64_t key = noise_key(1, 11);
  double sum = 0, sum2 = 0;
  int n = 0;
  for (int x = -20; x < 20; ++x) {
    for (int y = -20; y < 20; ++y) {
      const float v = lattice_value(key, x, y, 3);
      ASSERT_GE(v, -1.0f);
      ASSERT_LE(v, 1.0f);
      ASSERT_EQ(v, lattice_value(key, x, y, 3));
      sum += v;
      sum2 += v * v;
      ++n;
    }
  }
  EXPECT_NEAR(sum / n, 0.0, 0.05);
  EXPECT_NEAR(sum2 / n, 1.0 / 3.0, 0.05);  // uniform on [-1, 1]
  EXPECT_NE(lattice_value(noise_key(1, 11), 0, 0, 0), lattice_value(noise_key(2, 11), 0, 0, 0));
  EXPECT_NE(lattice_value(noise_key(1, 11), 0, 0, 0), lattice_value(noise_key(1, 12), 0, 0, 0));
}

TEST(SampleNoiseTest, KnownValuesStayTheSame) {
  // Pinned so that a change of the hash (and of every sample dataset) is noticed.
  EXPECT_EQ(mix64(0), 0u);
  EXPECT_EQ(mix64(1), 0x5692161d100b05e5ULL);
  const double u = unit_hash(noise_key(1, 1), 0);
  EXPECT_GE(u, 0.0);
  EXPECT_LT(u, 1.0);
}

TEST(SampleNoiseTest, FbmRowMatchesPointsAndStaysInRange) {
  const SampleGrid grid(Dims3{37, 23, 2});
  const FbmPlane fbm(FbmParams{48.0, 2.5, 4, 0.5, 1.0}, noise_key(5, 11), grid.x_km, grid.y_km,
                     1.7, 3.0, -2.0);
  std::vector<float> row(37);
  for (std::size_t j = 0; j < 23; ++j) {
    fbm.row(j, row);
    for (std::size_t i = 0; i < 37; ++i) {
      ASSERT_EQ(row[i], fbm.at(i, j)) << i << "," << j;
      ASSERT_LE(std::abs(row[i]), 1.0f);
    }
  }
  float total = 0;
  for (int o = 0; o < fbm.octaves(); ++o) total += fbm.amplitude(o);
  EXPECT_NEAR(total, 1.0f, 1e-6f);
  EXPECT_NEAR(fbm.remaining(0), 1.0f - fbm.amplitude(0), 1e-6f);
  EXPECT_EQ(fbm.remaining(fbm.octaves() - 1), 0.0f);
}

TEST(SampleNoiseTest, NoiseIsContinuousAcrossLatticeCells) {
  // Sampling densely along x, neighbouring values differ by little.
  std::vector<double> x(2001), y{0.0};
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = static_cast<double>(i) * 0.01;
  const NoisePlane plane(noise_key(3, 4), x, y, 1.0, 1.0, 0.0, 0.0, 0.25);
  std::vector<float> acc(x.size(), 0.0f);
  plane.accumulate_row(0, 1.0f, acc);
  for (std::size_t i = 0; i + 1 < acc.size(); ++i) ASSERT_LT(std::abs(acc[i + 1] - acc[i]), 0.05f);
}

TEST(SampleNoiseTest, ShiftMovesThePattern) {
  // fbm(x, shift s) == fbm(x - s): a field advected by s km.
  std::vector<double> x{10.0, 20.0, 30.0}, x_minus{7.0, 17.0, 27.0}, y{5.0};
  const FbmParams p{48.0, 2.5, 3, 0.5, 1.0};
  const FbmPlane shifted(p, noise_key(9, 1), x, y, 2.0, 3.0, 0.0);
  const FbmPlane plain(p, noise_key(9, 1), x_minus, y, 2.0, 0.0, 0.0);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(shifted.at(i, 0), plain.at(i, 0), 1e-5f);
}

}  // namespace
}  // namespace strielad::synthetic
