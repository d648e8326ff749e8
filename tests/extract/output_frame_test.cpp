// SPDX-License-Identifier: Apache-2.0
// Meshes moved from lon/lat/height axis coordinates into metric frames: WGS84 reference
// points, closed outward meshes stay closed and outward, unsupported axes are named.
#include <gtest/gtest.h>

#include <cmath>

#include "extract/mesh_metrics.h"
#include "extract/node_extractor.h"
#include "extract/output_frame.h"
#include "support/expect_error.h"
#include "support/mesh_normals.h"

namespace strielad {
namespace {

format::Manifest lon_lat_height(double lon0, double lon1, double lat0, double lat1, double h1,
                                std::size_t n) {
  format::Manifest m;
  auto fill = [n](Axis& a, std::string name, AxisKind kind, double lo, double hi) {
    a.name = std::move(name);
    a.kind = kind;
    for (std::size_t i = 0; i < n; ++i) a.values.push_back(lo + (hi - lo) * double(i) / double(n - 1));
  };
  fill(m.x, "lon", AxisKind::kLongitude, lon0, lon1);
  fill(m.y, "lat", AxisKind::kLatitude, lat0, lat1);
  fill(m.z, "height", AxisKind::kHeight, 0, h1);
  return m;
}

TEST(OutputFrameTest, EcefMatchesWgs84ReferencePoints) {
  const format::Manifest m = lon_lat_height(-1, 1, -1, 1, 1000, 3);
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {90, 0, 0}, {0, 90, 0}, {0, 0, 1000}};
  transform_mesh(mesh, m, OutputFrame::kEcef);
  EXPECT_NEAR(mesh.positions[0][0], 6378137.0, 1e-6);
  EXPECT_NEAR(mesh.positions[1][1], 6378137.0, 1e-6);
  EXPECT_NEAR(mesh.positions[1][0], 0.0, 1e-6);
  EXPECT_NEAR(mesh.positions[2][2], 6356752.314245, 1e-5);  // polar semi-axis b
  EXPECT_NEAR(mesh.positions[3][0], 6379137.0, 1e-6);
}

TEST(OutputFrameTest, ClosedMeshesStayClosedAndOutward) {
  // A blob 20 km across near 48N, 11E, 10 km high.
  const format::Manifest m = lon_lat_height(10.8, 11.2, 47.9, 48.1, 10000, 17);
  NodeSamples s;
  s.coords = {m.x.values, m.y.values, m.z.values};
  std::vector<float> f;
  for (double z : s.coords[2])
    for (double y : s.coords[1])
      for (double x : s.coords[0]) {
        const double dx = (x - 11.0) / 0.2, dy = (y - 48.0) / 0.1, dz = (z - 5000.0) / 5000.0;
        f.push_back(static_cast<float>(dx * dx + dy * dy + dz * dz));
      }
  s.fields.push_back(f);
  ExtractRequest r;
  r.limits = {{0, -kUnbounded, 0.6}};
  for (OutputFrame frame : {OutputFrame::kLocalMetric, OutputFrame::kEcef}) {
    Mesh mesh = extract_node_mesh(s, r);
    transform_mesh(mesh, m, frame);
    const MeshCheck c = check_mesh(mesh);
    EXPECT_TRUE(c.clean());
    // About an ellipsoid of semi-axes 0.775 * (14.9 km, 11.1 km, 5 km).
    const double v = enclosed_volume(mesh);
    const double expected = 4.0 / 3.0 * M_PI * std::pow(std::sqrt(0.6), 3) * 14.88e3 * 11.12e3 * 5e3;
    EXPECT_NEAR(v / expected, 1.0, 0.03) << static_cast<int>(frame);
    // Normals point away from the blob's centre.
    EXPECT_EQ(testing::normals_away_from_centroid(mesh), mesh.positions.size());
  }
}

TEST(OutputFrameTest, PressureLevelsArePlacedByTheStandardAtmosphere) {
  format::Manifest m = lon_lat_height(0, 1, 0, 1, 1, 2);
  m.z = Axis{"plev", AxisKind::kPressure, "hPa", "", "", "", {1000, 500}};
  const VerticalPlacement v = choose_vertical_placement(m);
  EXPECT_EQ(v.kind, VerticalPlacement::Kind::kStandardAtmosphere);
  EXPECT_NE(v.description.find("standard atmosphere"), std::string::npos);
  Mesh mesh;
  mesh.positions = {{0.5, 0.5, 500}, {0.5, 0.5, 226.32}};
  transform_mesh(mesh, m, OutputFrame::kLonLat);
  // ICAO: 500 hPa at 5574 m, 226.32 hPa at the tropopause, 11000 m.
  EXPECT_NEAR(mesh.positions[0][2], 5574.4, 1.0);
  EXPECT_NEAR(mesh.positions[1][2], 11000.0, 1.0);
  EXPECT_EQ(mesh.positions[0][0], 0.5);
  EXPECT_EQ(mesh.positions[0][1], 0.5);
}

TEST(OutputFrameTest, AGeopotentialVariablePlacesThemWhenTheStoreHasOne) {
  format::Manifest m = lon_lat_height(0, 1, 0, 1, 1, 2);
  m.z = Axis{"plev", AxisKind::kPressure, "Pa", "", "", "", {100000, 50000}};
  for (const char* name : {"t", "z"}) {
    format::StoreVariable v;
    v.name = name;
    v.units = std::string(name) == "z" ? "m**2 s**-2" : "K";
    m.variables.push_back(v);
  }
  const VerticalPlacement v = choose_vertical_placement(m);
  ASSERT_EQ(v.kind, VerticalPlacement::Kind::kHeightVariable);
  EXPECT_EQ(v.variable, "z");
  EXPECT_DOUBLE_EQ(v.metres_per_unit, 1.0 / 9.80665);
  Mesh mesh;
  mesh.positions = {{0.5, 0.5, 50000}};
  mesh.attribute_names = {"z"};
  mesh.attributes = {{55000.0f}};
  FrameTransform(m, OutputFrame::kLonLat, v).apply(mesh);
  EXPECT_NEAR(mesh.positions[0][2], 55000.0 / 9.80665, 1e-6);
  // Named explicitly; a variable that is not a height is refused naming its units.
  testing::expect_error([&] { choose_vertical_placement(m, "t"); }, ErrorCode::kUnsupported,
                        {"height variable 't' has units 'K'"});
  testing::expect_error([&] { choose_vertical_placement(m, "nope"); }, ErrorCode::kNotFound, {"nope"});
  // Meshes must carry it.
  Mesh bare;
  bare.positions = {{0.5, 0.5, 50000}};
  testing::expect_error([&] { FrameTransform(m, OutputFrame::kEcef, v).apply(bare); },
                        ErrorCode::kInvalidArgument, {"'z'", "attribute"});
}

TEST(OutputFrameTest, ModelLevelsWithoutAHeightAreRefused) {
  format::Manifest m = lon_lat_height(0, 1, 0, 1, 1, 2);
  m.z = Axis{"lev", AxisKind::kModelLevel, "1", "", "", "", {1, 2}};
  testing::expect_error([&] { choose_vertical_placement(m); }, ErrorCode::kUnsupported,
                        {"vertical axis 'lev' (model_level) has no height", "--height-var"});
  testing::expect_error([&] { parse_output_frame("utm"); }, ErrorCode::kInvalidArgument,
                        {"utm", "lonlat", "ecef"});
}

TEST(OutputFrameTest, ACartesianGridHasNoPlaceOnTheEarth) {
  format::Manifest m = lon_lat_height(0, 1000, 0, 1000, 100, 2);
  m.x.kind = AxisKind::kProjectionX;
  m.y.kind = AxisKind::kProjectionY;
  m.x.units = m.y.units = "m";
  m.z.units = "m";
  const VerticalPlacement v = choose_vertical_placement(m);
  for (OutputFrame f : {OutputFrame::kLonLat, OutputFrame::kEcef}) {
    testing::expect_error([&] { FrameTransform(m, f, v); }, ErrorCode::kUnsupported,
                          {"needs the grid's place on the Earth", "Cartesian"});
  }
  Mesh mesh;
  mesh.positions = {{1000, 0, 50}};
  FrameTransform(m, OutputFrame::kLocalMetric, v).apply(mesh);  // metres about the centre
  EXPECT_EQ(mesh.positions[0], (std::array<double, 3>{500, -500, 50}));
}

}  // namespace
}  // namespace strielad

namespace strielad {
namespace {

TEST(OutputFrameTest, MeshesPlacedByAGeopotentialOnPressureLevelsStayOutward) {
  // 1000 to 200 hPa with geopotential heights: the pressure axis grows downwards.
  format::Manifest m = lon_lat_height(10.8, 11.2, 47.9, 48.1, 1, 9);
  m.z = Axis{"plev", AxisKind::kPressure, "hPa", "", "", "", {}};
  for (int i = 0; i < 9; ++i) m.z.values.push_back(200.0 + 100.0 * i);
  format::StoreVariable t, z;
  t.name = "t";
  z.name = "z";
  z.units = "m";
  m.variables = {t, z};
  NodeSamples s;
  s.coords = {m.x.values, m.y.values, m.z.values};
  std::vector<float> blob, height;
  for (double p : s.coords[2])
    for (double y : s.coords[1])
      for (double x : s.coords[0]) {
        const double dx = (x - 11.0) / 0.15, dy = (y - 48.0) / 0.07, dz = (p - 600.0) / 250.0;
        blob.push_back(static_cast<float>(dx * dx + dy * dy + dz * dz));
        height.push_back(static_cast<float>(44330.8 * (1 - std::pow(p / 1013.25, 0.190263))));
      }
  s.fields = {blob, height};
  ExtractRequest r;
  r.limits = {{0, -kUnbounded, 0.6}};
  r.attribute_fields = {1};
  r.attribute_names = {"z"};
  Mesh mesh = extract_node_mesh(s, r);
  ASSERT_FALSE(mesh.triangles.empty());
  transform_mesh(mesh, m, OutputFrame::kLocalMetric);
  EXPECT_TRUE(check_mesh(mesh).closed());
  EXPECT_GT(enclosed_volume(mesh), 0);
}

}  // namespace
}  // namespace strielad
