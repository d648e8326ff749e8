// SPDX-License-Identifier: Apache-2.0
// The world frame on mapped grids (lib/lod/world_frame.h): a rotated-pole store lands in
// the world where PROJ's cs2cs puts its samples (true longitude/latitude on the plane
// tangent at the centre's true position), node boxes hold the curved image of their
// bricks, normals follow the curved grid, to_axis inverts to_world, geographic frames
// keep their world positions to the bit, Cartesian grids have no place on the Earth,
// and grids the plane cannot show are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "geo/cf_grid_mapping.h"
#include "lod/lod_test_grids.h"
#include "lod/world_frame.h"
#include "octree/octree_layout.h"
#include "support/cs2cs.h"
#include "support/expect_error.h"

namespace strielad::lod {
namespace {

using strielad::testing::expect_error;
using testing::linspace;

constexpr double kDeg = 3.14159265358979323846 / 180.0;

format::Manifest with_mapping(format::Manifest m, const std::string& variable, const std::string& name,
                              nlohmann::json attributes) {
  GridMapping g;
  g.variable = variable;
  g.name = name;
  g.attributes = std::move(attributes);
  g.attributes["grid_mapping_name"] = name;
  g.proj = geo::cf_grid_mapping_proj(g, m.x, m.y, "test");
  m.grid_mapping = g;
  return m;
}

// The EURO-CORDEX EUR-11 domain (rlon -28.375..18.155, rlat -23.375..21.835 on the pole
// 39.25 N, 162 W) at nx x ny samples, heights 0-10 km.
format::Manifest eur11_manifest(std::size_t nx, std::size_t ny, std::uint32_t brick = 8) {
  format::Manifest m;
  m.x = Axis{"rlon", AxisKind::kProjectionX, "degrees", "grid_longitude", "", "",
             linspace(-28.375, 18.155, nx)};
  m.y = Axis{"rlat", AxisKind::kProjectionY, "degrees", "grid_latitude", "", "",
             linspace(-23.375, 21.835, ny)};
  m.z = Axis{"height", AxisKind::kHeight, "m", "", "", "up", {0.0, 2000.0, 5000.0, 10000.0}};
  m.time = TimeAxis{"time", "days since 1949-12-01 00:00:00", "proleptic_gregorian", {20500.5}};
  m.brick = brick;
  return with_mapping(std::move(m), "rotated_pole", "rotated_latitude_longitude",
                      {{"grid_north_pole_latitude", 39.25}, {"grid_north_pole_longitude", -162.0}});
}

// cs2cs's true longitude/latitude of rotated points, on the plane tangent at `centre`.
std::vector<std::array<double, 2>> cs2cs_world(const std::vector<std::array<double, 2>>& rotated,
                                               std::array<double, 2> centre) {
  const auto g = strielad::testing::cs2cs(strielad::testing::kEuroCordexRotatedPole,
                                          "+proj=longlat", rotated);
  EXPECT_TRUE(g);
  std::vector<std::array<double, 2>> out;
  if (!g) return out;
  for (const auto& p : *g) {
    out.push_back({std::remainder(p[0] - centre[0], 360.0) * kKmPerDegree * std::cos(centre[1] * kDeg),
                   (p[1] - centre[1]) * kKmPerDegree});
  }
  return out;
}

TEST(WorldFrameMappedTest, RotatedPoleNodesLandWhereCs2csPutsTheirCornerSamples) {
  if (!strielad::testing::have_cs2cs()) GTEST_SKIP() << "cs2cs (proj-bin) missing";
  const format::Manifest m = eur11_manifest(43, 42);
  const WorldFrame frame(m);
  EXPECT_EQ(frame.horizontal(), HorizontalMap::kMapped);
  ASSERT_TRUE(frame.on_earth());
  // The tangent point: the true position of the centre of the rotated ranges.
  const double rlon_mid = 0.5 * (-28.375 + 18.155), rlat_mid = 0.5 * (-23.375 + 21.835);
  const auto centre = strielad::testing::cs2cs(strielad::testing::kEuroCordexRotatedPole,
                                               "+proj=longlat", {{rlon_mid, rlat_mid}});
  ASSERT_TRUE(centre);
  EXPECT_NEAR(frame.lon0(), (*centre)[0][0], 1e-9);
  EXPECT_NEAR(frame.lat0(), (*centre)[0][1], 1e-9);

  const OctreeLayout layout(m.dims(), m.brick);
  const auto boxes = node_world_boxes(layout, frame);
  EXPECT_EQ(boxes[layout.root()], frame.domain());
  for (NodeId id = 0; id < layout.node_count(); ++id) {
    const IndexBox fine = layout.fine_box(layout.key(id));
    std::vector<std::array<double, 2>> corners;
    std::vector<std::array<std::size_t, 2>> index;
    for (const std::size_t i : {fine.lo[0], fine.hi[0]}) {
      for (const std::size_t j : {fine.lo[1], fine.hi[1]}) {
        corners.push_back({m.x.values[i], m.y.values[j]});
        index.push_back({i, j});
      }
    }
    const auto expected = cs2cs_world(corners, (*centre)[0]);
    ASSERT_EQ(expected.size(), 4u);
    for (std::size_t c = 0; c < 4; ++c) {
      const auto w = frame.sample_world_xy(index[c][0], index[c][1]);
      EXPECT_NEAR(w[0], expected[c][0], 1e-6) << "node " << id << " corner " << c;
      EXPECT_NEAR(w[1], expected[c][1], 1e-6) << "node " << id << " corner " << c;
      const Vec3 p = frame.to_world({corners[c][0], corners[c][1], 0.0});
      EXPECT_NEAR(p[0], expected[c][0], 1e-6);
      EXPECT_NEAR(p[1], expected[c][1], 1e-6);
      // Within the node's box (up to cs2cs's printed digits, 1e-12 degrees).
      const WorldBox& b = boxes[id];
      EXPECT_TRUE(expected[c][0] >= b.lo[0] - 1e-6 && expected[c][0] <= b.hi[0] + 1e-6 &&
                  expected[c][1] >= b.lo[1] - 1e-6 && expected[c][1] <= b.hi[1] + 1e-6)
          << "node " << id;
    }
  }
  // The domain: Europe from the Canaries (about 22 N, 10 W at the south-western corner)
  // to the Urals; its plane spans some 6,000 x 5,000 km.
  const auto b = frame.geographic_bounds();
  EXPECT_LT(b.lon_lo, -40.0);
  EXPECT_GT(b.lon_hi, 60.0);
  EXPECT_NEAR(b.lat_lo, 20.0, 3.0);
  EXPECT_NEAR(b.lat_hi, 73.0, 3.0);
}

TEST(WorldFrameMappedTest, NodeBoxesHoldTheCurvedImageOfTheirBricks) {
  // Coarse samples (1.1 degrees) bend the grid lines between samples by kilometres.
  const format::Manifest m = eur11_manifest(43, 42, 4);
  const WorldFrame frame(m);
  const OctreeLayout layout(m.dims(), m.brick);
  const auto boxes = node_world_boxes(layout, frame);
  double worst_pad = 0;
  for (NodeId id = 0; id < layout.node_count(); ++id) {
    const IndexBox fine = layout.fine_box(layout.key(id));
    const double x0 = m.x.values[fine.lo[0]], x1 = m.x.values[fine.hi[0]];
    const double y0 = m.y.values[fine.lo[1]], y1 = m.y.values[fine.hi[1]];
    WorldBox dense{{INFINITY, INFINITY, 0}, {-INFINITY, -INFINITY, 0}};
    constexpr int kSteps = 64;
    for (int a = 0; a <= kSteps; ++a) {
      for (int c = 0; c <= kSteps; ++c) {
        const double x = x0 + (x1 - x0) * a / kSteps, y = y0 + (y1 - y0) * c / kSteps;
        const Vec3 p = frame.to_world({x, y, m.z.values[fine.lo[2]]});
        ASSERT_TRUE(boxes[id].contains(p)) << "node " << id << " at " << x << ", " << y;
        for (int k = 0; k < 2; ++k) {
          dense.lo[k] = std::min(dense.lo[k], p[k]);
          dense.hi[k] = std::max(dense.hi[k], p[k]);
        }
      }
    }
    for (int k = 0; k < 2; ++k) {
      worst_pad = std::max({worst_pad, dense.lo[k] - boxes[id].lo[k], boxes[id].hi[k] - dense.hi[k]});
    }
  }
  // Conservative, not loose: at most a few km on a 6,000 km domain of 130 km cells.
  EXPECT_LT(worst_pad, 5.0);
  EXPECT_GT(worst_pad, 0.0);
}

TEST(WorldFrameMappedTest, ToAxisInvertsToWorld) {
  const WorldFrame frame(eur11_manifest(43, 42));
  for (const Vec3& p : {Vec3{-28.375, -23.375, 0}, Vec3{0, 0, 2000}, Vec3{18.155, 21.835, 10000},
                        Vec3{-5.5, 12.25, 123.4}}) {
    const Vec3 back = frame.to_axis(frame.to_world(p));
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(back[a], p[a], 1e-9 * (1 + std::fabs(p[a]))) << a;
  }
  // True longitude/latitude to the axes and back through the plane.
  const auto xy = frame.geographic_to_world(11.4, 47.27);  // Innsbruck
  const auto axis = frame.geographic_to_axis(11.4, 47.27);
  const Vec3 w = frame.to_world({axis[0], axis[1], 0});
  EXPECT_NEAR(w[0], xy[0], 1e-6);
  EXPECT_NEAR(w[1], xy[1], 1e-6);
  // Beyond the pole the plane has no place.
  const Vec3 far = frame.to_axis({0, 1e5, 0});
  EXPECT_TRUE(std::isnan(far[0]) && std::isnan(far[1]));
}

TEST(WorldFrameMappedTest, NormalsStayPerpendicularToTheCurvedGrid) {
  const WorldFrame frame(eur11_manifest(43, 42));
  // The surface x = const has axis normal (1, 0, 0): in the world it must be
  // perpendicular to the image of the grid line x = const and to the vertical.
  for (const auto& [x, y] : {std::pair{-20.0, -15.0}, std::pair{10.0, 18.0}, std::pair{0.3, 0.7}}) {
    const Vec3 n = frame.normal_to_world({x, y, 1000.0}, {1, 0, 0});
    const Vec3 a = frame.to_world({x, y - 0.01, 1000.0}), b = frame.to_world({x, y + 0.01, 1000.0});
    const Vec3 along = normalize(sub(b, a));
    EXPECT_NEAR(dot(n, along), 0.0, 2e-3) << x << ", " << y;
    EXPECT_NEAR(n[2], 0.0, 1e-12);
    EXPECT_NEAR(length(n), 1.0, 1e-12);
    // Outward: towards increasing x.
    const Vec3 c = frame.to_world({x + 0.01, y, 1000.0}), d = frame.to_world({x - 0.01, y, 1000.0});
    EXPECT_GT(dot(n, sub(c, d)), 0.0);
  }
  EXPECT_FALSE(frame.mirrored());
}

TEST(WorldFrameMappedTest, GeographicFramesKeepTheirWorldPositionsToTheBit) {
  const format::Manifest m = testing::paper_manifest();
  const WorldFrame f(m);
  EXPECT_EQ(f.horizontal(), HorizontalMap::kGeographic);
  const double kx = kKmPerDegree * std::cos(51.0 * kDeg);
  for (std::size_t i = 0; i < m.x.size(); i += 97) {
    for (std::size_t j = 0; j < m.y.size(); j += 89) {
      const auto w = f.sample_world_xy(i, j);
      EXPECT_EQ(w[0], (m.x.values[i] - 9.5) * kx);
      EXPECT_EQ(w[1], (m.y.values[j] - 51.0) * kKmPerDegree);
      const Vec3 p = f.to_world({m.x.values[i], m.y.values[j], 0.0});
      EXPECT_EQ(p[0], w[0]);
      EXPECT_EQ(p[1], w[1]);
      const auto g = f.geographic_to_world(m.x.values[i], m.y.values[j]);
      EXPECT_EQ(g[0], w[0]);
      EXPECT_EQ(g[1], w[1]);
    }
  }
  // A longitude a turn away is the same place.
  EXPECT_EQ(f.geographic_to_world(9.5 + 2.0 - 360.0, 51.0)[0], f.geographic_to_world(11.5, 51.0)[0]);
}

TEST(WorldFrameMappedTest, CartesianGridsHaveNoPlaceOnTheEarth) {
  format::Manifest m = testing::geographic_manifest(5, 5, {0.0, 1000.0});
  m.x = Axis{"x", AxisKind::kProjectionX, "m", "projection_x_coordinate", "", "",
             linspace(0, 40000, 5)};
  m.y = Axis{"y", AxisKind::kProjectionY, "m", "projection_y_coordinate", "", "",
             linspace(0, 40000, 5)};
  const WorldFrame f(m);
  EXPECT_EQ(f.horizontal(), HorizontalMap::kMetric);
  EXPECT_FALSE(f.on_earth());
  EXPECT_NEAR(f.to_world({40000, 0, 0})[0], 20.0, 1e-12);
  for (const auto& call : {std::function<void()>([&] { f.geographic_to_world(10, 50); }),
                           std::function<void()>([&] { f.geographic_bounds(); }),
                           std::function<void()>([&] { f.lon0(); })}) {
    expect_error(call, ErrorCode::kUnsupported, {"'x'", "'y'", "grid_mapping", "Earth"});
  }
}

TEST(WorldFrameMappedTest, ProjectedGridInKilometresIsPlacedByPROJ) {
  // A Lambert conformal grid like the NCEP Eta's (km), centred at 40 N, 100 W.
  format::Manifest m = testing::geographic_manifest(9, 9, {0.0, 5000.0});
  m.x = Axis{"x", AxisKind::kProjectionX, "km", "projection_x_coordinate", "", "",
             linspace(-2000, 2000, 9)};
  m.y = Axis{"y", AxisKind::kProjectionY, "km", "projection_y_coordinate", "", "",
             linspace(-1500, 1500, 9)};
  m = with_mapping(m, "lambert", "lambert_conformal_conic",
                   {{"standard_parallel", {33.0, 45.0}},
                    {"longitude_of_central_meridian", -100.0},
                    {"latitude_of_projection_origin", 40.0},
                    {"earth_radius", 6371229.0}});
  const WorldFrame f(m);
  EXPECT_EQ(f.horizontal(), HorizontalMap::kMapped);
  EXPECT_NEAR(f.lon0(), -100.0, 1e-9);
  EXPECT_NEAR(f.lat0(), 40.0, 1e-9);
  EXPECT_DOUBLE_EQ(f.axis_length_km(0), 1.0);
  // Distances near the centre are the map's (scale factor about 1 near 40 N).
  const Vec3 p = f.to_world({100, 0, 0});
  EXPECT_NEAR(p[0], 100.0, 2.0);
  EXPECT_NEAR(p[1], 0.0, 2.0);
}

TEST(WorldFrameMappedTest, RefusesGridsAroundAPole) {
  // A polar stereographic grid of the Arctic holds the pole: its image on a plane tangent
  // at the centre tears at the meridian opposite the centre.
  format::Manifest m = testing::geographic_manifest(9, 9, {0.0, 5000.0});
  m.x = Axis{"x", AxisKind::kProjectionX, "m", "projection_x_coordinate", "", "",
             linspace(-3e6, 2e6, 9)};
  m.y = Axis{"y", AxisKind::kProjectionY, "m", "projection_y_coordinate", "", "",
             linspace(-3e6, 2e6, 9)};
  m = with_mapping(m, "polar", "polar_stereographic",
                   {{"straight_vertical_longitude_from_pole", -45.0},
                    {"latitude_of_projection_origin", 90.0},
                    {"standard_parallel", 70.0}});
  expect_error([&] { WorldFrame{m}; }, ErrorCode::kUnsupported, {"'polar'", "opposite"});
}

TEST(WorldFrameMappedTest, PressureAxisMirrorsTheMappedFrame) {
  format::Manifest m = eur11_manifest(9, 9);
  m.z = Axis{"plev", AxisKind::kPressure, "hPa", "", "", "down", {1000.0, 850.0, 500.0}};
  const WorldFrame f(m);
  EXPECT_TRUE(f.mirrored());
  EXPECT_NEAR(f.sample_world_z(2) / kDefaultVerticalExaggeration, 5.574, 0.002);
}

}  // namespace
}  // namespace strielad::lod
