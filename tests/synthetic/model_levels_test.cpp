// SPDX-License-Identifier: Apache-2.0
// The terrain-following level coefficients of the model-like samples: hybrid height
// levels flat at the top and on the ground at the bottom, hybrid sigma-pressure levels
// ordered in every plausible column; column_height inverts column_pressure.
#include <gtest/gtest.h>

#include "synthetic/atmosphere_profiles.h"
#include "synthetic/model_levels.h"
#include "synthetic/sample_grid.h"

namespace strielad::synthetic {
namespace {

TEST(ModelLevelsTest, HybridHeightRunsFromAFlatTopToTheGround) {
  for (const std::size_t nz : {1u, 2u, 30u, 150u}) {
    const HybridHeightLevels l = hybrid_height_levels(nz);
    ASSERT_EQ(l.half_a.size(), nz + 1);
    ASSERT_EQ(l.full_a.size(), nz);
    EXPECT_EQ(l.half_a.front(), kModelTop);
    EXPECT_EQ(l.half_b.front(), 0.0);
    EXPECT_EQ(l.half_a.back(), 0.0);
    EXPECT_EQ(l.half_b.back(), 1.0);
    for (std::size_t k = 0; k < nz; ++k) {
      EXPECT_GT(l.half_a[k], l.half_a[k + 1]) << nz << " " << k;
      EXPECT_LT(l.half_b[k], l.half_b[k + 1]) << nz << " " << k;
      EXPECT_DOUBLE_EQ(l.full_a[k], 0.5 * (l.half_a[k] + l.half_a[k + 1]));
      EXPECT_DOUBLE_EQ(l.full_b[k], 0.5 * (l.half_b[k] + l.half_b[k + 1]));
      // Ordered over a 5 km mountain, more than the sample terrain's highest.
      EXPECT_GT(l.half_a[k] + 5000.0 * l.half_b[k], l.half_a[k + 1] + 5000.0 * l.half_b[k + 1]);
    }
  }
  // The terrain's imprint is mostly gone well below the top.
  const HybridHeightLevels l = hybrid_height_levels(150);
  for (std::size_t k = 0; k < 150; ++k) {
    if (l.half_a[k] > 15000.0) {
      EXPECT_LT(l.half_b[k], 0.5);
    }
  }
}

TEST(ModelLevelsTest, HybridSigmaPressureIsOrderedInEveryColumn) {
  for (const std::size_t nz : {1u, 3u, 60u, 137u}) {
    const HybridPressureLevels l = hybrid_pressure_levels(nz);
    ASSERT_EQ(l.half_ap.size(), nz + 1);
    ASSERT_EQ(l.full_ap.size(), nz);
    EXPECT_EQ(l.half_b.front(), 0.0);
    EXPECT_NEAR(l.half_ap.front(), column_pressure(kModelTop, kHybridReferencePressure, 0.0),
                1e-6);
    EXPECT_EQ(l.half_ap.back(), 0.0);
    EXPECT_EQ(l.half_b.back(), 1.0);
    for (const double ps : {40000.0, 55000.0, 80000.0, 101325.0, 105000.0}) {
      for (std::size_t k = 0; k < nz; ++k) {
        EXPECT_LT(l.half_ap[k] + l.half_b[k] * ps, l.half_ap[k + 1] + l.half_b[k + 1] * ps)
            << nz << " " << ps << " " << k;
        const double p = l.full_ap[k] + l.full_b[k] * ps;
        EXPECT_GT(p, l.half_ap[k] + l.half_b[k] * ps);
        EXPECT_LT(p, l.half_ap[k + 1] + l.half_b[k + 1] * ps);
      }
    }
  }
}

TEST(ModelLevelsTest, ColumnHeightInvertsColumnPressure) {
  for (const double dt : {-8.0, 0.0, 5.0}) {
    for (const double z : {0.0, 500.0, 3000.0, 10999.0, 11000.0, 15000.0, 21000.0}) {
      const double p = column_pressure(z, 100800.0, dt);
      EXPECT_NEAR(column_height(p, 100800.0, dt), z, 1e-6) << dt << " " << z;
    }
  }
}

}  // namespace
}  // namespace strielad::synthetic
