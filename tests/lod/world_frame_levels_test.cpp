// SPDX-License-Identifier: Apache-2.0
// The world frame of a terrain-following store (lod/world_frame.h, VerticalMap::
// kLevelHeights): model levels counted from the top placed piecewise-linearly between one
// representative height per level, the inverse, monotonic maps, a `levels` geometry
// table, and what it refuses (a field without heights, bad tables).
#include <gtest/gtest.h>

#include <cmath>

#include "geo/standard_atmosphere.h"
#include "lod/lod_test_grids.h"
#include "lod/world_frame.h"
#include "support/expect_error.h"

namespace strielad::lod {
namespace {

using strielad::testing::expect_error;
using testing::geographic_manifest;

// ICON-like: 'height' 1..6 counted from the top, a geometry field of heights.
format::Manifest model_level_manifest() {
  format::Manifest m =
      geographic_manifest(9, 7, {1, 2, 3, 4, 5, 6}, AxisKind::kModelLevel, "1");
  format::GridGeometry g;
  g.vertical.kind = format::VerticalGeometry::Kind::kField;
  g.vertical.quantity = format::VerticalGeometry::Quantity::kHeight;
  g.vertical.units = "m";
  m.geometry = g;
  return m;
}

// Heights of levels 1..6, top down, unevenly spaced as model levels are.
const std::vector<double> kHeights{12000, 8000, 5000, 2500, 1000, 200};

TEST(WorldFrameLevelsTest, LevelsMapPiecewiseLinearlyAndRoundTrip) {
  const WorldFrame f(model_level_manifest(),
                     WorldFrameOptions{2.0}, kHeights);
  EXPECT_EQ(f.vertical(), VerticalMap::kLevelHeights);
  for (std::size_t k = 0; k < kHeights.size(); ++k) {
    EXPECT_DOUBLE_EQ(f.sample_world_z(k), kHeights[k] * 1e-3 * 2.0);
    EXPECT_DOUBLE_EQ(f.vertical_to_world(double(k + 1)), kHeights[k] * 1e-3 * 2.0);
  }
  // Half-way between levels 2 and 3: half-way between their heights.
  EXPECT_NEAR(f.vertical_to_world(2.5), 0.5 * (8.0 + 5.0) * 2.0, 1e-12);
  // Beyond the ends: the end cells continued.
  EXPECT_NEAR(f.vertical_to_world(0.5), (12000 + 2000) * 1e-3 * 2.0, 1e-9);
  EXPECT_DOUBLE_EQ(f.domain().lo[2], 0.4);
  EXPECT_DOUBLE_EQ(f.domain().hi[2], 24.0);
  // Level index grows downwards: the map reverses z.
  EXPECT_TRUE(f.mirrored());
  EXPECT_LT(f.vertical_unit(), 0);
  // Round trip and strict monotonicity over and beyond the axis.
  double last = INFINITY;
  for (double z = 0.25; z <= 6.75; z += 0.125) {
    const double w = f.vertical_to_world(z);
    EXPECT_LT(w, last) << z;
    last = w;
    EXPECT_NEAR(f.world_to_vertical(w), z, 1e-12) << z;
    const Vec3 p = f.to_axis(f.to_world({9.0, 51.0, z}));
    EXPECT_NEAR(p[2], z, 1e-12);
  }
  // The same at another exaggeration.
  const WorldFrame g = f.with_exaggeration(10.0);
  EXPECT_DOUBLE_EQ(g.sample_world_z(5), 2.0);
  EXPECT_NEAR(g.world_to_vertical(g.vertical_to_world(3.3)), 3.3, 1e-12);
}

TEST(WorldFrameLevelsTest, NodeBoxesFollowTheLevelHeights) {
  const format::Manifest m = model_level_manifest();
  const WorldFrame f(m, WorldFrameOptions{1.0}, kHeights);
  const WorldBox b = f.index_box_world(IndexBox{{0, 0, 1}, {8, 6, 3}});
  EXPECT_DOUBLE_EQ(b.lo[2], 2.5);
  EXPECT_DOUBLE_EQ(b.hi[2], 8.0);
}

TEST(WorldFrameLevelsTest, AGeometryLevelTableMapsByItself) {
  format::Manifest m = geographic_manifest(9, 7, {1, 2, 3}, AxisKind::kModelLevel, "1");
  format::GridGeometry g;
  g.vertical.kind = format::VerticalGeometry::Kind::kLevels;
  g.vertical.quantity = format::VerticalGeometry::Quantity::kPressure;
  g.vertical.units = "Pa";
  g.vertical.levels = {20000, 50000, 90000};
  m.geometry = g;
  const WorldFrame f(m, WorldFrameOptions{1.0});
  EXPECT_EQ(f.vertical(), VerticalMap::kLevelHeights);
  EXPECT_NEAR(f.sample_world_z(1), geo::standard_height_m(50000) * 1e-3, 1e-9);
  EXPECT_NEAR(f.world_to_vertical(f.sample_world_z(2)), 3.0, 1e-12);
}

TEST(WorldFrameLevelsTest, RefusesAFieldWithoutHeightsAndBadTables) {
  expect_error([] { WorldFrame f(model_level_manifest()); }, ErrorCode::kUnsupported,
               {"'height'", "level_heights_m"});
  expect_error(
      [] {
        WorldFrame f(model_level_manifest(),
                     WorldFrameOptions{}, {12000, 8000, 5000});
      },
      ErrorCode::kInvalidArgument, {"3 level heights", "6 samples"});
  expect_error(
      [] {
        WorldFrame f(model_level_manifest(),
                     WorldFrameOptions{}, {12000, 8000, 9000, 2500, 1000, 200});
      },
      ErrorCode::kInvalidArgument, {"index 2", "monotonic"});
  expect_error(
      [] {
        WorldFrame f(model_level_manifest(),
                     WorldFrameOptions{}, {12000, 8000, NAN, 2500, 1000, 200});
      },
      ErrorCode::kInvalidArgument, {"index 2"});
  // A model-level axis without a geometry stays refused.
  expect_error(
      [] { WorldFrame f(geographic_manifest(9, 7, {1, 2, 3}, AxisKind::kModelLevel, "1")); },
      ErrorCode::kUnsupported, {"only height and pressure"});
}

}  // namespace
}  // namespace strielad::lod
