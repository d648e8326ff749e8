// SPDX-License-Identifier: Apache-2.0
// The geometry suite's harness in quick mode: the four samples convert, the terrain-
// following stores record their geometry (stored once for ICON, per step for sigma-
// pressure) and their placed extraction reads one more brick per node with triangles;
// the curvilinear store's geometry is its 2-D coordinates, placed without a brick.
#include <gtest/gtest.h>

#include <filesystem>

#include "bench/geometry_bench.h"

namespace strielad::testing {
namespace {

TEST(GeometrySuiteQuickTest, SamplesConvertAndPlacedExtractionReadsTheGeometry) {
  bench::GeometryBenchOptions o = bench::quick_geometry_options({});
  o.work = std::filesystem::temp_directory_path() / "strielad_geometry_suite_quick_test";
  std::filesystem::remove_all(o.work);
  const auto report = bench::run_geometry_bench(o);
  ASSERT_EQ(report.inputs.size(), 4u);
  const auto& rect = report.inputs[0];
  const auto& icon = report.inputs[1];
  const auto& sigma = report.inputs[2];
  const auto& curvilinear = report.inputs[3];
  EXPECT_EQ(rect.geometry_bytes, 0u);
  EXPECT_GT(icon.geometry_bytes, 0u);
  EXPECT_GT(sigma.geometry_bytes, 0u);
  EXPECT_NE(icon.geometry.find("z_ifc"), std::string::npos);
  EXPECT_NE(sigma.geometry.find("per step"), std::string::npos);
  EXPECT_GT(curvilinear.geometry_bytes, 0u);  // GEOMETRY's longitudes and latitudes
  EXPECT_NE(curvilinear.geometry.find("2-D lon/lat"), std::string::npos) << curvilinear.geometry;
  EXPECT_EQ(curvilinear.bricks_placed, curvilinear.bricks_axis);
  for (const auto& r : report.inputs) {
    ASSERT_EQ(r.convert_seconds.size(), 1u);
    ASSERT_EQ(r.placed_seconds.size(), 1u);
    EXPECT_GT(r.triangles_placed, 0u) << r.name;
  }
  // Only ICON's geometry bricks are shared by the steps: the kept-cache run is its alone.
  EXPECT_EQ(icon.placed_warm_seconds.size(), 1u);
  EXPECT_TRUE(rect.placed_warm_seconds.empty());
  EXPECT_TRUE(sigma.placed_warm_seconds.empty());
  EXPECT_TRUE(curvilinear.placed_warm_seconds.empty());
  EXPECT_EQ(rect.bricks_placed, rect.bricks_axis);  // the height axis needs no brick
  EXPECT_GT(icon.bricks_placed, icon.bricks_axis);
  EXPECT_LE(icon.bricks_placed, 2 * icon.bricks_axis);
  const auto tables = bench::geometry_tables(report);
  ASSERT_EQ(tables.size(), 2u);
  EXPECT_EQ(tables[0].rows.size(), 4u);
  std::filesystem::remove_all(o.work);
}

}  // namespace
}  // namespace strielad::testing
