// SPDX-License-Identifier: Apache-2.0
// The world frame (lib/lod/world_frame.h): geographic and metric horizontal axes,
// height and pressure vertical axes (ICAO standard atmosphere), descending axes, the
// vertical exaggeration, the inverse map, the axes it refuses, and node world boxes.
#include "lod/world_frame.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geo/standard_atmosphere.h"
#include "lod/lod_test_grids.h"
#include "octree/octree_layout.h"
#include "support/expect_error.h"

namespace strielad::lod {
namespace {

using strielad::testing::expect_error;
using testing::geographic_manifest;
using testing::linspace;

constexpr double kDeg = 3.14159265358979323846 / 180.0;

format::Manifest heights_manifest() {
  return geographic_manifest(11, 8, {12000.0, 3000.0, 0.0});
}

TEST(WorldFrameTest, GeographicAxesBecomeKilometresFromTheDomainCentre) {
  const WorldFrame f(heights_manifest());
  EXPECT_EQ(f.horizontal(), HorizontalMap::kGeographic);
  EXPECT_EQ(f.vertical(), VerticalMap::kHeight);
  EXPECT_DOUBLE_EQ(f.lon0(), 9.5);   // midpoint of 4.5..14.5
  EXPECT_DOUBLE_EQ(f.lat0(), 51.0);  // midpoint of 54.5..47.5
  const Vec3 c = f.to_world({9.5, 51.0, 0.0});
  EXPECT_NEAR(c[0], 0, 1e-12);
  EXPECT_NEAR(c[1], 0, 1e-12);
  EXPECT_NEAR(c[2], 0, 1e-12);
  const Vec3 p = f.to_world({10.5, 52.0, 1000.0});
  EXPECT_NEAR(p[0], 111.195 * std::cos(51.0 * kDeg), 1e-3);
  EXPECT_NEAR(p[1], 111.195, 1e-3);
  EXPECT_NEAR(p[2], 1.0 * kDefaultVerticalExaggeration, 1e-12);  // 1 km, exaggerated
}

TEST(WorldFrameTest, DescendingAxesMapByValueNotStorageOrder) {
  const WorldFrame f(heights_manifest());
  // Latitude stored north to south: sample 0 is the northernmost, largest y.
  EXPECT_GT(f.sample_world_xy(0, 0)[1], f.sample_world_xy(0, 7)[1]);
  // Height stored top down: sample 0 is the highest.
  EXPECT_DOUBLE_EQ(f.sample_world_z(0), 120.0);
  EXPECT_DOUBLE_EQ(f.sample_world_z(2), 0.0);
  const WorldBox& d = f.domain();
  for (int a = 0; a < 3; ++a) EXPECT_LT(d.lo[a], d.hi[a]);
  EXPECT_NEAR(d.lo[1], -3.5 * 111.195, 1e-2);
  EXPECT_NEAR(d.hi[1], 3.5 * 111.195, 1e-2);
  EXPECT_DOUBLE_EQ(d.lo[2], 0.0);
  EXPECT_DOUBLE_EQ(d.hi[2], 120.0);
}

TEST(WorldFrameTest, VerticalExaggerationScalesOnlyZ) {
  const WorldFrame one(heights_manifest(), WorldFrameOptions{1.0});
  const WorldFrame ten(heights_manifest());
  const Vec3 a = one.to_world({7.0, 50.0, 3000.0});
  const Vec3 b = ten.to_world({7.0, 50.0, 3000.0});
  EXPECT_DOUBLE_EQ(a[0], b[0]);
  EXPECT_DOUBLE_EQ(a[1], b[1]);
  EXPECT_DOUBLE_EQ(a[2], 3.0);
  EXPECT_DOUBLE_EQ(b[2], 30.0);
  expect_error([] { WorldFrame(heights_manifest(), WorldFrameOptions{0.0}); },
               ErrorCode::kInvalidArgument, {"vertical exaggeration"});
  expect_error([] { WorldFrame(heights_manifest(), WorldFrameOptions{NAN}); },
               ErrorCode::kInvalidArgument, {"vertical exaggeration"});
}

TEST(WorldFrameTest, MetricAxesInMetresOrKilometres) {
  format::Manifest m = heights_manifest();
  m.x.units = "m";
  m.x.values = linspace(0, 200000, 5);
  m.y.units = "km";
  m.y.values = linspace(300, 100, 3);  // descending
  m.z.units = "km";
  m.z.values = {0.0, 1.5, 12.0};
  const WorldFrame f(m, WorldFrameOptions{2.0});
  EXPECT_EQ(f.horizontal(), HorizontalMap::kMetric);
  const Vec3 p = f.to_world({150000, 250, 1.5});
  EXPECT_DOUBLE_EQ(p[0], 50.0);  // 150 km from the 100 km midpoint
  EXPECT_DOUBLE_EQ(p[1], 50.0);
  EXPECT_DOUBLE_EQ(p[2], 3.0);   // 1.5 km, exaggerated twice
}

TEST(WorldFrameTest, StandardAtmosphereMatchesTheIcaoTable) {
  // Layer bases of ISO 2533 / US Standard Atmosphere 1976 (geopotential height).
  EXPECT_NEAR(geo::standard_height_m(101325.0), 0.0, 1e-9);
  EXPECT_NEAR(geo::standard_height_m(22632.06), 11000.0, 0.5);
  EXPECT_NEAR(geo::standard_height_m(5474.889), 20000.0, 1.0);
  EXPECT_NEAR(geo::standard_height_m(868.0187), 32000.0, 2.0);
  EXPECT_NEAR(geo::standard_height_m(110.9063), 47000.0, 3.0);
  EXPECT_NEAR(geo::standard_height_m(66.93887), 51000.0, 3.0);
  EXPECT_NEAR(geo::standard_height_m(3.956420), 71000.0, 5.0);
  EXPECT_NEAR(geo::standard_height_m(0.3733836), 84852.0, 10.0);
  // Familiar levels: 850 hPa ~ 1457 m, 500 hPa ~ 5574 m, 200 hPa ~ 11784 m.
  EXPECT_NEAR(geo::standard_height_m(85000.0), 1457.0, 2.0);
  EXPECT_NEAR(geo::standard_height_m(50000.0), 5574.0, 2.0);
  EXPECT_NEAR(geo::standard_height_m(20000.0), 11784.0, 3.0);
  EXPECT_LT(geo::standard_height_m(105000.0), 0.0);       // below sea level
  EXPECT_TRUE(std::isnan(geo::standard_height_m(0.0)));
  EXPECT_TRUE(std::isnan(geo::standard_height_m(-5.0)));
  // Strictly decreasing in pressure and inverted by standard_pressure_pa, far beyond
  // the table.
  double previous = -INFINITY;
  for (double pa = 2e5; pa > 1e-12; pa *= 0.8) {
    const double h = geo::standard_height_m(pa);
    EXPECT_GT(h, previous) << pa;
    previous = h;
    EXPECT_NEAR(geo::standard_pressure_pa(h), pa, pa * 1e-9) << pa;
  }
}

TEST(WorldFrameTest, PressureAxesMapThroughTheStandardAtmosphere) {
  const WorldFrame hpa(geographic_manifest(5, 5, {1000, 850, 500, 200, 100}, AxisKind::kPressure,
                                           "hPa"));
  EXPECT_EQ(hpa.vertical(), VerticalMap::kPressure);
  EXPECT_NEAR(hpa.sample_world_z(2), 5.574 * kDefaultVerticalExaggeration, 0.02);
  EXPECT_GT(hpa.sample_world_z(4), hpa.sample_world_z(0));  // low pressure is high up
  const WorldFrame pa(geographic_manifest(5, 5, {100000, 85000, 50000, 20000, 10000},
                                          AxisKind::kPressure, "Pa"));
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_NEAR(pa.sample_world_z(i), hpa.sample_world_z(i), 1e-9);
  }
  const WorldFrame mbar(geographic_manifest(5, 5, {1000, 850, 500, 200, 100}, AxisKind::kPressure,
                                            "mbar"));
  EXPECT_NEAR(mbar.sample_world_z(3), hpa.sample_world_z(3), 1e-9);
}

TEST(WorldFrameTest, ToAxisInvertsToWorld) {
  const WorldFrame geo(heights_manifest());
  const WorldFrame pressure(geographic_manifest(5, 5, {1000, 850, 500, 200, 100},
                                                AxisKind::kPressure, "hPa"));
  for (const Vec3& p : {Vec3{4.5, 54.5, 0}, Vec3{12.25, 48.0, 7321.5}, Vec3{-30, 80, 250000}}) {
    const Vec3 back = geo.to_axis(geo.to_world(p));
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(back[a], p[a], 1e-9 * (1 + std::fabs(p[a])));
  }
  for (const Vec3& p : {Vec3{9.5, 51, 1000}, Vec3{5, 53, 123.4}, Vec3{9, 50, 1e-6}}) {
    const Vec3 back = pressure.to_axis(pressure.to_world(p));
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(back[a], p[a], 1e-8 * std::fabs(p[a]) + 1e-12);
  }
}

TEST(WorldFrameTest, RefusesAxesWithoutAWorldPosition) {
  format::Manifest model = heights_manifest();
  model.z.kind = AxisKind::kModelLevel;
  model.z.name = "lev";
  model.z.units = "";
  expect_error([&] { WorldFrame{model}; }, ErrorCode::kUnsupported, {"'lev'", "model_level"});

  format::Manifest other = heights_manifest();
  other.x.kind = AxisKind::kOther;
  other.x.name = "rlon";
  other.x.units = "degrees";
  expect_error([&] { WorldFrame{other}; }, ErrorCode::kUnsupported, {"'rlon'"});

  format::Manifest unitless = geographic_manifest(3, 3, {1000, 500}, AxisKind::kPressure, "");
  expect_error([&] { WorldFrame{unitless}; }, ErrorCode::kUnsupported, {"'plev'", "units"});

  format::Manifest feet = heights_manifest();
  feet.z.units = "ft";
  expect_error([&] { WorldFrame{feet}; }, ErrorCode::kUnsupported, {"'height'", "'ft'"});

  format::Manifest zero = geographic_manifest(3, 3, {1000, 500, 0}, AxisKind::kPressure, "hPa");
  expect_error([&] { WorldFrame{zero}; }, ErrorCode::kInvalidInput, {"'plev'", "index 2"});

  format::Manifest nan = heights_manifest();
  nan.y.values[3] = NAN;
  expect_error([&] { WorldFrame{nan}; }, ErrorCode::kInvalidInput, {"grid.y"});

  format::Manifest polar = heights_manifest();
  polar.y.values = {89.99, 90.0};
  expect_error([&] { WorldFrame{polar}; }, ErrorCode::kUnsupported, {"'lat'", "pole"});
}

TEST(WorldFrameTest, NodeBoxesNestAndTileTheDomainOnThePaperGrid) {
  const format::Manifest m = testing::paper_manifest();
  const OctreeLayout layout(m.dims(), m.brick);
  ASSERT_EQ(layout.node_count(), 51393u);
  const WorldFrame frame(m);
  const std::vector<WorldBox> boxes = node_world_boxes(layout, frame);
  ASSERT_EQ(boxes.size(), layout.node_count());
  EXPECT_EQ(boxes[layout.root()], frame.domain());

  auto volume = [](const WorldBox& b) {
    return (b.hi[0] - b.lo[0]) * (b.hi[1] - b.lo[1]) * (b.hi[2] - b.lo[2]);
  };
  const WorldBox& d = frame.domain();
  for (std::size_t l = 0; l < layout.level_count(); ++l) {
    const LevelShape& s = layout.level(l);
    double total = 0;
    for (NodeId id = s.first_node; id < s.first_node + s.node_count(); ++id) {
      const WorldBox& b = boxes[id];
      ASSERT_TRUE(d.contains(b)) << id;
      total += volume(b);
      for (NodeId c : layout.children(id)) ASSERT_TRUE(b.contains(boxes[c])) << c << " in " << id;
    }
    // The boxes of one level share faces and cover the domain: volumes add up.
    EXPECT_NEAR(total, volume(d), volume(d) * 1e-9) << "level " << l;
  }
}

TEST(WorldFrameTest, NodeBoxesNeedTheManifestsGrid) {
  const WorldFrame frame(heights_manifest());
  const OctreeLayout other(Dims3{12, 8, 3}, 4);
  expect_error([&] { node_world_boxes(other, frame); }, ErrorCode::kInvalidArgument,
               {"12x8x3", "11x8x3"});
}

}  // namespace
}  // namespace strielad::lod
