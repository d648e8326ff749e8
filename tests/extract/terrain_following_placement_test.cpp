// SPDX-License-Identifier: Apache-2.0
// Meshes of a terrain-following grid placed by the store's grid geometry: every vertex at
// the height its attribute carries, closed meshes staying closed and outward whichever way
// the level index runs, per-level tables interpolated between levels, and what cannot be
// placed refused.
#include <gtest/gtest.h>

#include <cmath>

#include "format/geometry_field.h"
#include "extract/mesh_metrics.h"
#include "extract/node_extractor.h"
#include "extract/output_frame.h"
#include "support/expect_error.h"
#include "support/mesh_normals.h"

namespace strielad {
namespace {

constexpr std::size_t kN = 17;

Axis axis(std::string name, AxisKind kind, double lo, double hi, std::size_t n) {
  Axis a;
  a.name = std::move(name);
  a.kind = kind;
  for (std::size_t i = 0; i < n; ++i) a.values.push_back(lo + (hi - lo) * double(i) / double(n - 1));
  return a;
}

// lon 10.8..11.2, lat 47.9..48.1, model levels 1..kN numbered from the top (ICON): the
// height falls as k grows. Geometry: a field of heights, orientation -1.
format::Manifest top_down_levels() {
  format::Manifest m;
  m.x = axis("lon", AxisKind::kLongitude, 10.8, 11.2, kN);
  m.y = axis("lat", AxisKind::kLatitude, 47.9, 48.1, kN);
  m.z = axis("height", AxisKind::kModelLevel, 1, double(kN), kN);
  format::GridGeometry g;
  g.vertical.kind = format::VerticalGeometry::Kind::kField;
  g.vertical.quantity = format::VerticalGeometry::Quantity::kHeight;
  g.vertical.units = "m";
  g.vertical.formula = "variable";
  g.vertical.sources = {"z_ifc"};
  g.orientation = -1;
  m.geometry = g;
  return m;
}

// Terrain: a 1500 m ridge along the domain; levels from 10 km (k = 0) down to the ground,
// following the terrain less with height.
double terrain(double lon) { return 1500.0 * std::exp(-std::pow((lon - 11.0) / 0.08, 2)); }
double level_height(double lon, std::size_t k) {
  const double s = 1.0 - double(k) / double(kN - 1);  // 1 at the top, 0 at the ground
  return 10000.0 * s + terrain(lon) * (1.0 - s) * (1.0 - s);
}

// Samples: a blob of cloud centred at 5 km height above (11.0, 48.0), and the heights.
NodeSamples terrain_following_samples(const format::Manifest& m) {
  NodeSamples s;
  s.coords = {m.x.values, m.y.values, m.z.values};
  std::vector<float> blob, height;
  for (std::size_t k = 0; k < kN; ++k)
    for (double y : m.y.values)
      for (double x : m.x.values) {
        const double h = level_height(x, k);
        const double dx = (x - 11.0) / 0.15, dy = (y - 48.0) / 0.07, dz = (h - 5000.0) / 3000.0;
        blob.push_back(static_cast<float>(dx * dx + dy * dy + dz * dz));
        height.push_back(static_cast<float>(h));
      }
  s.fields = {blob, height};
  return s;
}

Mesh blob_mesh(const format::Manifest& m, bool axis_normals = true) {
  ExtractRequest r;
  r.axis_normals = axis_normals;
  r.limits = {{0, -kUnbounded, 0.6}};
  r.attribute_fields = {1};
  r.attribute_names = {format::geometry_field_name(m)};
  return extract_node_mesh(terrain_following_samples(m), r);
}

TEST(TerrainFollowingPlacementTest, VerticesSitAtTheGeometrysHeight) {
  const format::Manifest m = top_down_levels();
  const VerticalPlacement v = choose_vertical_placement(m);
  ASSERT_EQ(v.kind, VerticalPlacement::Kind::kGeometry);
  EXPECT_EQ(v.attribute, "geometry_height");
  EXPECT_EQ(v.vertical_sign, -1);
  EXPECT_NE(v.description.find("z_ifc"), std::string::npos);
  Mesh mesh = blob_mesh(m);
  ASSERT_FALSE(mesh.triangles.empty());
  const std::vector<float> heights = mesh.attributes.at(0);
  const std::vector<std::array<double, 3>> axis_positions = mesh.positions;
  FrameTransform(m, OutputFrame::kLonLat, v).apply(mesh);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    EXPECT_EQ(mesh.positions[i][2], static_cast<double>(heights[i]));
    EXPECT_EQ(mesh.positions[i][0], axis_positions[i][0]);
    EXPECT_EQ(mesh.positions[i][1], axis_positions[i][1]);
  }
}

TEST(TerrainFollowingPlacementTest, MeshesStayClosedAndOutwardWhenLevelsCountDownwards) {
  const format::Manifest m = top_down_levels();
  for (OutputFrame frame : {OutputFrame::kLonLat, OutputFrame::kLocalMetric, OutputFrame::kEcef}) {
    Mesh mesh = blob_mesh(m);
    FrameTransform(m, frame, choose_vertical_placement(m)).apply(mesh);
    const MeshCheck c = check_mesh(mesh);
    EXPECT_TRUE(c.closed()) << output_frame_name(frame);
    EXPECT_GT(enclosed_volume(mesh), 0) << output_frame_name(frame);
    if (frame != OutputFrame::kLocalMetric) continue;
    // About an ellipsoid of semi-axes sqrt(0.6) * (11.2 km, 7.8 km, 3 km).
    const double expected = 4.0 / 3.0 * M_PI * std::pow(std::sqrt(0.6), 3) * 11.16e3 * 7.78e3 * 3e3;
    EXPECT_NEAR(enclosed_volume(mesh) / expected, 1.0, 0.05);
    EXPECT_EQ(testing::normals_away_from_centroid(mesh), mesh.positions.size());
  }
}

// The placed surface's normals replace the axis frame's: extracting without those gives
// the same placed mesh, bit for bit, in every frame.
TEST(TerrainFollowingPlacementTest, MeshesExtractedWithoutAxisNormalsArePlacedTheSame) {
  const format::Manifest m = top_down_levels();
  for (OutputFrame frame : {OutputFrame::kLonLat, OutputFrame::kLocalMetric, OutputFrame::kEcef}) {
    const FrameTransform transform(m, frame, choose_vertical_placement(m));
    EXPECT_TRUE(transform.replaces_normals());
    Mesh with = blob_mesh(m), without = blob_mesh(m, false);
    ASSERT_FALSE(without.triangles.empty());
    EXPECT_EQ(without.positions, with.positions);
    transform.apply(with);
    transform.apply(without);
    EXPECT_TRUE(without == with) << output_frame_name(frame);
  }
  EXPECT_FALSE(FrameTransform(m, OutputFrame::kAxis, choose_vertical_placement(m)).replaces_normals());
}

TEST(TerrainFollowingPlacementTest, PressureFieldsArePlacedByTheStandardAtmosphere) {
  format::Manifest m = top_down_levels();
  m.geometry->vertical.quantity = format::VerticalGeometry::Quantity::kPressure;
  m.geometry->vertical.units = "Pa";
  const VerticalPlacement v = choose_vertical_placement(m);
  EXPECT_EQ(v.attribute, "geometry_pressure");
  EXPECT_TRUE(v.pressure);
  Mesh mesh;
  mesh.positions = {{11, 48, 3}};
  mesh.attribute_names = {"geometry_pressure"};
  mesh.attributes = {{50000.0f}};
  FrameTransform(m, OutputFrame::kLonLat, v).apply(mesh);
  EXPECT_NEAR(mesh.positions[0][2], 5574.4, 1.0);  // ICAO: 500 hPa at 5574 m
}

TEST(TerrainFollowingPlacementTest, LevelTablesAreInterpolatedBetweenLevels) {
  format::Manifest m = top_down_levels();
  m.z = axis("lev", AxisKind::kModelLevel, 3, 1, 3);  // descending axis values
  m.geometry->vertical.kind = format::VerticalGeometry::Kind::kLevels;
  m.geometry->vertical.levels = {100, 200, 400};
  m.geometry->orientation = 1;
  const VerticalPlacement v = choose_vertical_placement(m);
  EXPECT_TRUE(v.attribute.empty());
  EXPECT_EQ(v.vertical_sign, -1);  // heights grow with k, the axis values fall with k
  Mesh mesh;
  mesh.positions = {{11, 48, 3}, {11, 48, 2.5}, {11, 48, 1.25}, {11, 48, 1}};
  FrameTransform(m, OutputFrame::kLonLat, v).apply(mesh);
  EXPECT_DOUBLE_EQ(mesh.positions[0][2], 100);
  EXPECT_DOUBLE_EQ(mesh.positions[1][2], 150);
  EXPECT_DOUBLE_EQ(mesh.positions[2][2], 350);
  EXPECT_DOUBLE_EQ(mesh.positions[3][2], 400);
}

TEST(TerrainFollowingPlacementTest, WhatCannotBePlacedIsRefused) {
  format::Manifest m = top_down_levels();
  testing::expect_error([&] { choose_vertical_placement(m, "zg"); }, ErrorCode::kInvalidArgument,
                        {"--height-var zg", "grid geometry"});
  Mesh bare;
  bare.positions = {{11, 48, 3}};
  testing::expect_error(
      [&] { FrameTransform(m, OutputFrame::kLonLat, choose_vertical_placement(m)).apply(bare); },
      ErrorCode::kInvalidArgument, {"geometry_height", "attribute"});
  m.geometry->horizontal.kind = format::HorizontalGeometry::Kind::kCurvilinear;
  m.geometry->horizontal.lon_variable = "XLONG";
  m.geometry->horizontal.lat_variable = "XLAT";
  // A curvilinear grid is placed by its GEOMETRY coordinates: none given, none placed.
  testing::expect_error(
      [&] { FrameTransform(m, OutputFrame::kLonLat, choose_vertical_placement(m)); },
      ErrorCode::kUnsupported, {"curvilinear", "XLONG", "GEOMETRY"});
}

}  // namespace
}  // namespace strielad
