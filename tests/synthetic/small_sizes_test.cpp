// SPDX-License-Identifier: Apache-2.0
// Tiny and odd grids work and hold finite values of every variable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <ostream>

#include "sample_test_util.h"

namespace strielad {
void PrintTo(const Dims3& d, std::ostream* os) { *os << d.x << "x" << d.y << "x" << d.z; }
}  // namespace strielad

namespace strielad::testing {
namespace {

class SampleSmallSizeTest : public ::testing::TestWithParam<Dims3> {};

TEST_P(SampleSmallSizeTest, WritesEveryVariableWithFiniteValues) {
  const Dims3 dims = GetParam();
  const GeneratedSample s(small_spec(dims, 2));
  ASSERT_EQ(s.result.files.size(), 2u);
  for (std::size_t t = 0; t < 2; ++t) {
    const NcFile f(s.file(t));
    EXPECT_EQ(f.dim_length("lon"), dims.x);
    EXPECT_EQ(f.dim_length("lat"), dims.y);
    EXPECT_EQ(f.dim_length("height"), dims.z);
    EXPECT_EQ(f.dim_length("time"), 1u);
    EXPECT_EQ(f.doubles("lon").size(), dims.x);
    for (const auto& name : synthetic::all_sample_variable_names()) {
      const auto values = f.floats(name);
      ASSERT_EQ(values.size(), dims.count()) << name;
      for (const float v : values) ASSERT_TRUE(std::isfinite(v)) << name;
    }
    for (const float ta : f.floats("ta")) {
      EXPECT_GT(ta, 195.0f);
      EXPECT_LT(ta, 315.0f);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, SampleSmallSizeTest,
                         ::testing::Values(Dims3{2, 2, 2}, Dims3{7, 5, 3}, Dims3{1, 1, 1},
                                           Dims3{1, 9, 2}, Dims3{13, 1, 4}),
                         [](const auto& info) {
                           return std::to_string(info.param.x) + "x" +
                                  std::to_string(info.param.y) + "x" +
                                  std::to_string(info.param.z);
                         });

TEST(SampleSmallSizeTest, CoarseGridSamplesTheSameAtmosphere) {
  // A grid of (2n - 1) points contains every point of the n-point grid of the same
  // domain; those points carry the same values.
  auto coarse_spec = small_spec(Dims3{9, 7, 6});
  auto fine_spec = small_spec(Dims3{17, 13, 6});
  coarse_spec.variables = fine_spec.variables = {"ta", "ua", "clw"};
  const GeneratedSample coarse(coarse_spec), fine(fine_spec);
  const NcFile c(coarse.file()), f(fine.file());
  for (const char* name : {"ta", "ua", "clw"}) {
    for (std::size_t k = 0; k < 6; ++k) {
      const auto cv = c.level(name, 0, k), fv = f.level(name, 0, k);
      for (std::size_t j = 0; j < 7; ++j) {
        for (std::size_t i = 0; i < 9; ++i) {
          EXPECT_NEAR(cv[j * 9 + i], fv[(2 * j) * 17 + 2 * i], 1e-4f * std::abs(cv[j * 9 + i]) + 1e-9f)
              << name << " level " << k << " at " << i << "," << j;
        }
      }
    }
  }
}

}  // namespace
}  // namespace strielad::testing
