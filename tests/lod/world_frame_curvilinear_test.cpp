// SPDX-License-Identifier: Apache-2.0
// The world frame on curvilinear grids (lib/lod/world_frame.h, lib/lod/curvilinear_plane.h):
// a store known only by its 2-D longitudes and latitudes lands where those coordinates
// (here PROJ's cs2cs positions of a rotated-pole grid) say, on the plane tangent at the
// centre column; positions between columns are bilinear, node boxes hold every placed
// point, to_axis and geographic_to_axis invert the map inside and beyond the grid, normals
// follow the grid's turn, and what the plane cannot show is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

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

// A curvilinear store's manifest: index axes 0..n-1, heights 0-10 km.
format::Manifest curvilinear_manifest(std::size_t nx, std::size_t ny, std::uint32_t brick = 8) {
  format::Manifest m;
  m.x = Axis{"x", AxisKind::kIndex, "1", "", "", "", linspace(0, double(nx - 1), nx)};
  m.y = Axis{"y", AxisKind::kIndex, "1", "", "", "", linspace(0, double(ny - 1), ny)};
  m.z = Axis{"height", AxisKind::kHeight, "m", "", "", "up", {0.0, 2000.0, 5000.0, 10000.0}};
  m.time = TimeAxis{"time", "hours since 2020-01-01 00:00:00", "standard", {0.0}};
  m.brick = brick;
  m.geometry = format::GridGeometry{};
  m.geometry->horizontal.kind = format::HorizontalGeometry::Kind::kCurvilinear;
  m.geometry->horizontal.lon_variable = "lon";
  m.geometry->horizontal.lat_variable = "lat";
  return m;
}

// cs2cs's true positions of a rotated-pole grid (EURO-CORDEX's pole), rotated longitude
// `rlon0` + 0.44 i and latitude `rlat0` + 0.44 j, as a curvilinear grid's coordinates.
std::shared_ptr<format::HorizontalCoordinates> rotated_coordinates(std::size_t nx, std::size_t ny,
                                                                   double rlon0 = -10,
                                                                   double rlat0 = -8) {
  std::vector<std::array<double, 2>> rotated;
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) rotated.push_back({rlon0 + 0.44 * i, rlat0 + 0.44 * j});
  }
  const auto g = strielad::testing::cs2cs(strielad::testing::kEuroCordexRotatedPole,
                                          "+proj=longlat", rotated);
  auto c = std::make_shared<format::HorizontalCoordinates>();
  c->nx = static_cast<std::uint32_t>(nx);
  c->ny = static_cast<std::uint32_t>(ny);
  if (!g) return c;
  for (const auto& p : *g) {
    c->lon.push_back(p[0]);
    c->lat.push_back(p[1]);
  }
  return c;
}

std::array<double, 2> plane(const WorldFrame& f, double lon, double lat) {
  return {std::remainder(lon - f.lon0(), 360.0) * kKmPerDegree * std::cos(f.lat0() * kDeg),
          (lat - f.lat0()) * kKmPerDegree};
}

TEST(WorldFrameCurvilinearTest, ColumnsLandWhereTheirOwnCoordinatesSay) {
  if (!strielad::testing::have_cs2cs()) GTEST_SKIP() << "cs2cs (proj-bin) missing";
  const std::size_t nx = 41, ny = 37;
  const auto c = rotated_coordinates(nx, ny);
  ASSERT_EQ(c->lon.size(), nx * ny);
  const format::Manifest m = curvilinear_manifest(nx, ny);
  const WorldFrame f(m, {}, {}, c);
  EXPECT_EQ(f.horizontal(), HorizontalMap::kCurvilinear);
  EXPECT_TRUE(f.bends_grid_lines());
  ASSERT_TRUE(f.on_earth());
  // The tangent point is the centre column (20, 18).
  EXPECT_NEAR(f.lon0(), c->lon[18 * nx + 20], 1e-12);
  EXPECT_NEAR(f.lat0(), c->lat[18 * nx + 20], 1e-12);
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const auto want = plane(f, c->lon[j * nx + i], c->lat[j * nx + i]);
      const Vec3 w = f.to_world({double(i), double(j), 5000.0});
      ASSERT_NEAR(w[0], want[0], 1e-9) << i << "," << j;
      ASSERT_NEAR(w[1], want[1], 1e-9) << i << "," << j;
      EXPECT_DOUBLE_EQ(w[2], 5.0 * kDefaultVerticalExaggeration);
      const auto g = f.world_to_geographic(w[0], w[1]);
      EXPECT_NEAR(std::remainder(g[0] - c->lon[j * nx + i], 360.0), 0.0, 1e-9);
      EXPECT_NEAR(g[1], c->lat[j * nx + i], 1e-9);
      EXPECT_EQ(f.sample_world_xy(i, j), (std::array<double, 2>{w[0], w[1]}));
    }
  }
  EXPECT_NE(f.describe_horizontal().find("'lon' / 'lat'"), std::string::npos);
}

TEST(WorldFrameCurvilinearTest, PositionsBetweenColumnsAreBilinear) {
  if (!strielad::testing::have_cs2cs()) GTEST_SKIP() << "cs2cs (proj-bin) missing";
  const auto c = rotated_coordinates(9, 7);
  const WorldFrame f(curvilinear_manifest(9, 7), {}, {}, c);
  const auto at = [&](std::size_t i, std::size_t j) { return f.sample_world_xy(i, j); };
  const double s = 0.3, t = 0.8;
  const Vec3 w = f.to_world({4 + s, 2 + t, 0});
  for (int k = 0; k < 2; ++k) {
    const double bottom = (1 - s) * at(4, 2)[k] + s * at(5, 2)[k];
    const double top = (1 - s) * at(4, 3)[k] + s * at(5, 3)[k];
    EXPECT_NEAR(w[k], (1 - t) * bottom + t * top, 1e-12);
  }
}

TEST(WorldFrameCurvilinearTest, NodeBoxesHoldEveryPlacedPoint) {
  if (!strielad::testing::have_cs2cs()) GTEST_SKIP() << "cs2cs (proj-bin) missing";
  const std::size_t nx = 41, ny = 37;
  const format::Manifest m = curvilinear_manifest(nx, ny, 8);
  const WorldFrame f(m, {}, {}, rotated_coordinates(nx, ny));
  const OctreeLayout layout(m.dims(), m.brick);
  const auto boxes = node_world_boxes(layout, f);
  EXPECT_EQ(boxes[layout.root()], f.domain());
  std::mt19937 rng(7);
  for (NodeId id = 0; id < layout.node_count(); ++id) {
    const IndexBox b = layout.fine_box(layout.key(id));
    std::uniform_real_distribution<double> ui(double(b.lo[0]), double(b.hi[0]));
    std::uniform_real_distribution<double> uj(double(b.lo[1]), double(b.hi[1]));
    for (int k = 0; k < 50; ++k) {
      const Vec3 p = f.to_world({ui(rng), uj(rng), m.z.values[b.lo[2]]});
      EXPECT_TRUE(boxes[id].contains(p)) << "node " << id;
    }
  }
}

TEST(WorldFrameCurvilinearTest, ToAxisInvertsToWorldInsideAndBeyondTheGrid) {
  if (!strielad::testing::have_cs2cs()) GTEST_SKIP() << "cs2cs (proj-bin) missing";
  const std::size_t nx = 41, ny = 37;
  const WorldFrame f(curvilinear_manifest(nx, ny), {}, {}, rotated_coordinates(nx, ny));
  std::mt19937 rng(11);
  // Inside, and up to a whole domain beyond every side (camera positions).
  std::uniform_real_distribution<double> ui(-40.0, 80.0), uj(-37.0, 73.0), uz(0.0, 10000.0);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 axis{ui(rng), uj(rng), uz(rng)};
    const Vec3 world = f.to_world(axis);
    const Vec3 back = f.to_axis(world);
    ASSERT_TRUE(std::isfinite(back[0]) && std::isfinite(back[1])) << axis[0] << "," << axis[1];
    const Vec3 again = f.to_world(back);
    EXPECT_NEAR(again[0], world[0], 1e-6) << axis[0] << "," << axis[1];
    EXPECT_NEAR(again[1], world[1], 1e-6) << axis[0] << "," << axis[1];
    EXPECT_NEAR(back[2], axis[2], 1e-6);
    const bool inside = axis[0] >= 0 && axis[0] <= nx - 1 && axis[1] >= 0 && axis[1] <= ny - 1;
    if (inside) {
      EXPECT_NEAR(back[0], axis[0], 1e-9);
      EXPECT_NEAR(back[1], axis[1], 1e-9);
    }
  }
}

TEST(WorldFrameCurvilinearTest, GeographicToAxisFindsTheColumnOfItsCoordinates) {
  if (!strielad::testing::have_cs2cs()) GTEST_SKIP() << "cs2cs (proj-bin) missing";
  const std::size_t nx = 23, ny = 19;
  const auto c = rotated_coordinates(nx, ny);
  const WorldFrame f(curvilinear_manifest(nx, ny), {}, {}, c);
  for (std::size_t j = 0; j < ny; j += 3) {
    for (std::size_t i = 0; i < nx; i += 2) {
      const auto a = f.geographic_to_axis(c->lon[j * nx + i], c->lat[j * nx + i]);
      EXPECT_NEAR(a[0], double(i), 1e-8);
      EXPECT_NEAR(a[1], double(j), 1e-8);
    }
  }
  const auto none = f.geographic_to_axis(0.0, 91.0);
  EXPECT_TRUE(std::isnan(none[0]) && std::isnan(none[1]));
}

TEST(WorldFrameCurvilinearTest, NormalsTurnWithTheGrid) {
  if (!strielad::testing::have_cs2cs()) GTEST_SKIP() << "cs2cs (proj-bin) missing";
  const std::size_t nx = 41, ny = 37;
  const WorldFrame f(curvilinear_manifest(nx, ny), {}, {}, rotated_coordinates(nx, ny));
  // The normal of a face i = const is perpendicular to the image of the grid line along j.
  for (const double i : {3.25, 20.5, 38.75}) {
    const Vec3 n = f.normal_to_world({i, 10.5, 1000.0}, {1, 0, 0});
    const Vec3 a = f.to_world({i, 10.0, 1000.0}), b = f.to_world({i, 11.0, 1000.0});
    const double along = n[0] * (b[0] - a[0]) + n[1] * (b[1] - a[1]);
    EXPECT_NEAR(along, 0.0, 1e-9 * std::hypot(b[0] - a[0], b[1] - a[1]));
    // It points towards growing i.
    const Vec3 e = f.to_world({i + 0.5, 10.5, 1000.0}), o = f.to_world({i, 10.5, 1000.0});
    EXPECT_GT(n[0] * (e[0] - o[0]) + n[1] * (e[1] - o[1]), 0.0);
    EXPECT_NEAR(n[2], 0.0, 1e-12);
  }
}

TEST(WorldFrameCurvilinearTest, AGridWhoseRowsRunSouthIsMirrored) {
  if (!strielad::testing::have_cs2cs()) GTEST_SKIP() << "cs2cs (proj-bin) missing";
  const std::size_t nx = 9, ny = 7;
  const auto c = rotated_coordinates(nx, ny);
  const WorldFrame north(curvilinear_manifest(nx, ny), {}, {}, c);
  auto flipped = std::make_shared<format::HorizontalCoordinates>(*c);
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      flipped->lon[j * nx + i] = c->lon[(ny - 1 - j) * nx + i];
      flipped->lat[j * nx + i] = c->lat[(ny - 1 - j) * nx + i];
    }
  }
  const WorldFrame south(curvilinear_manifest(nx, ny), {}, {}, flipped);
  EXPECT_FALSE(north.mirrored());
  EXPECT_TRUE(south.mirrored());
}

TEST(WorldFrameCurvilinearTest, WhatThePlaneCannotShowIsRefused) {
  const std::size_t nx = 6, ny = 5;
  const format::Manifest m = curvilinear_manifest(nx, ny);
  auto regular = std::make_shared<format::HorizontalCoordinates>();
  regular->nx = nx;
  regular->ny = ny;
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      regular->lon.push_back(10.0 + i);
      regular->lat.push_back(45.0 + j);
    }
  }
  EXPECT_NO_THROW(WorldFrame(m, {}, {}, regular));
  expect_error([&] { WorldFrame f(m); }, ErrorCode::kUnsupported,
               {"curvilinear grid ('lon' / 'lat')", "GEOMETRY"});
  expect_error([&] { WorldFrame f(curvilinear_manifest(nx + 1, ny), {}, {}, regular); },
               ErrorCode::kInvalidArgument, {"6 x 5", "7 x 5"});
  auto folded = std::make_shared<format::HorizontalCoordinates>(*regular);
  std::swap(folded->lon[2 * nx + 2], folded->lon[2 * nx + 3]);
  expect_error([&] { WorldFrame f(m, {}, {}, folded); }, ErrorCode::kUnsupported,
               {"folded", "column (2, 1) to (3, 2)"});
  // Round the Earth: columns 80 degrees apart, the last beyond the opposite meridian.
  auto round = std::make_shared<format::HorizontalCoordinates>(*regular);
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) round->lon[j * nx + i] = -150.0 + 80.0 * i;
  }
  expect_error([&] { WorldFrame f(m, {}, {}, round); }, ErrorCode::kUnsupported,
               {"both sides of longitude"});
}

}  // namespace
}  // namespace strielad::lod
