// SPDX-License-Identifier: Apache-2.0
// ColumnOrderCheck: terrain-following columns checked level by level as they stream past.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "ingest/vertical_columns.h"
#include "support/expect_error.h"

namespace strielad::ingest {
namespace {

using strielad::testing::expect_error;

TEST(VerticalColumnOrderTest, RisingAndFallingColumnsPass) {
  ColumnOrderCheck rising(2, 1, "f.nc: z_mc");
  rising.add_level(4, std::vector<double>{0.0, 10.0});
  rising.add_level(5, std::vector<double>{1.0, 10.5});
  EXPECT_EQ(rising.direction(), 1);
  ColumnOrderCheck falling(2, 1, "f.nc: z_mc");
  falling.add_level(0, std::vector<double>{9.0, 10.0});
  falling.add_level(1, std::vector<double>{1.0, 2.0});
  falling.add_level(2, std::vector<double>{0.5, -2.0});
  EXPECT_EQ(falling.direction(), -1);
}

TEST(VerticalColumnOrderTest, RepeatedValueNamesTheSample) {
  ColumnOrderCheck check(2, 2, "f.nc: z_mc time step 3");
  check.add_level(0, std::vector<double>{0.0, 0.0, 0.0, 0.0});
  expect_error(
      [&] {
        check.add_level(1, std::vector<double>{1.0, 1.0, 1.0, 0.0});
      },
      ErrorCode::kInvalidInput,
      {"f.nc: z_mc time step 3", "(i 1, j 1, k 1)", "not strictly monotonic"});
}

TEST(VerticalColumnOrderTest, ColumnRunningTheOtherWayNamesTheSample) {
  ColumnOrderCheck check(3, 1, "f.nc: HHL");
  check.add_level(0, std::vector<double>{0.0, 0.0, 0.0});
  check.add_level(1, std::vector<double>{1.0, 1.0, 1.0});
  expect_error(
      [&] {
        check.add_level(2, std::vector<double>{2.0, 0.5, 3.0});
      },
      ErrorCode::kInvalidInput, {"f.nc: HHL", "(i 1, j 0, k 2)", "other way"});
}

TEST(VerticalColumnOrderTest, FirstColumnFlatIsRefused) {
  ColumnOrderCheck check(1, 1, "f.nc");
  check.add_level(0, std::vector<double>{5.0});
  expect_error([&] { check.add_level(1, std::vector<double>{5.0}); }, ErrorCode::kInvalidInput,
               {"column (i 0, j 0)", "level 0 and level 1"});
}

TEST(VerticalColumnOrderTest, NonFiniteValueNamesTheSample) {
  ColumnOrderCheck check(2, 1, "f.nc");
  expect_error(
      [&] {
        check.add_level(7, std::vector<double>{1.0, std::numeric_limits<double>::quiet_NaN()});
      },
      ErrorCode::kInvalidInput, {"(i 1, j 0, k 7)"});
}

TEST(VerticalColumnOrderTest, LevelsOutOfOrderOrOfTheWrongSizeAreRefused) {
  ColumnOrderCheck check(2, 1, "f.nc");
  check.add_level(0, std::vector<double>{1.0, 2.0});
  expect_error(
      [&] {
        check.add_level(2, std::vector<double>{2.0, 3.0});
      },
      ErrorCode::kInvalidArgument, {"level 2", "after level 0"});
  expect_error([&] { check.add_level(1, std::vector<double>{2.0}); }, ErrorCode::kInvalidArgument,
               {"holds 1 values"});
}

}  // namespace
}  // namespace strielad::ingest
