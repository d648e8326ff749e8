// SPDX-License-Identifier: Apache-2.0
// The globe shape of the world frame (lib/lod/world_frame.h, lib/lod/wgs84_globe.h): the
// automatic choice of the globe, ECEF positions against PROJ's cs2cs, round trips, normals,
// up directions, and node boxes that hold every placed point of their bricks.
#include <gtest/gtest.h>

#include <cmath>

#include "lod/lod_test_grids.h"
#include "lod/wgs84_globe.h"
#include "lod/world_frame.h"
#include "octree/octree_layout.h"
#include "support/cs2cs.h"
#include "support/expect_error.h"

namespace strielad::lod {
namespace {

using strielad::testing::expect_error;
using testing::linspace;

// A grid of lon_span x lat_span degrees centred at (lon_c, lat_c), heights 0..20 km.
format::Manifest domain(double lon_c, double lat_c, double lon_span, double lat_span,
                        std::size_t nx = 9, std::size_t ny = 7, std::size_t nz = 5,
                        std::uint32_t brick = 8) {
  format::Manifest m = testing::geographic_manifest(nx, ny, linspace(0.0, 20000.0, nz));
  m.x.values = linspace(lon_c - lon_span / 2, lon_c + lon_span / 2, nx);
  m.y.values = linspace(lat_c + lat_span / 2, lat_c - lat_span / 2, ny);
  m.brick = brick;
  return m;
}

// A global 7.5-degree grid (as the 2.5-degree forecasts, coarser): longitude 0..352.5,
// latitude 90..-90 (poles included), heights 0..30 km.
format::Manifest global_grid(std::size_t nz = 9, std::uint32_t brick = 8) {
  format::Manifest m = testing::geographic_manifest(48, 25, linspace(0.0, 30000.0, nz));
  m.x.values = linspace(0.0, 352.5, 48);
  m.y.values = linspace(90.0, -90.0, 25);
  m.brick = brick;
  return m;
}

WorldFrameOptions shape(FrameShape s, double exaggeration = 1.0) {
  return {.vertical_exaggeration = exaggeration, .shape = s};
}

double distance(const Vec3& a, const Vec3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

TEST(WorldFrameGlobeTest, AutoChoosesTheGlobeForWideAndGlobalDomains) {
  EXPECT_FALSE(WorldFrame(domain(10, 50, 20, 15), shape(FrameShape::kAuto)).globe());
  EXPECT_TRUE(WorldFrame(domain(10, 50, 40, 15), shape(FrameShape::kAuto)).globe());
  EXPECT_TRUE(WorldFrame(domain(10, 20, 20, 40), shape(FrameShape::kAuto)).globe());
  EXPECT_TRUE(WorldFrame(global_grid(), shape(FrameShape::kAuto)).globe());
  // The default stays the plane; a small domain can be asked for the globe.
  EXPECT_FALSE(WorldFrame(global_grid()).globe());
  EXPECT_TRUE(WorldFrame(domain(10, 50, 5, 5), shape(FrameShape::kGlobe)).globe());
  EXPECT_FALSE(WorldFrame(domain(10, 50, 5, 5), shape(FrameShape::kPlane)).globe());
}

TEST(WorldFrameGlobeTest, CartesianGridsKeepThePlaneOrRefuseTheGlobe) {
  format::Manifest m = domain(0, 0, 1, 1);
  m.x = Axis{"x", AxisKind::kProjectionX, "km", "", "", "", linspace(0, 5000, 9)};
  m.y = Axis{"y", AxisKind::kProjectionY, "km", "", "", "", linspace(0, 5000, 7)};
  EXPECT_FALSE(WorldFrame(m, shape(FrameShape::kAuto)).globe());
  expect_error([&] { WorldFrame(m, shape(FrameShape::kGlobe)); }, ErrorCode::kUnsupported,
               {"globe", "'x'"});
}

TEST(WorldFrameGlobeTest, PositionsAreWgs84EcefAsProjPlacesThem) {
  if (!strielad::testing::have_cs2cs()) GTEST_SKIP() << "cs2cs (proj-bin) not installed";
  const WorldFrame f(global_grid(), shape(FrameShape::kAuto));
  ASSERT_TRUE(f.globe());
  std::vector<std::array<double, 3>> in;
  std::vector<Vec3> ours;
  for (double lon : {0.0, 37.5, 90.0, 179.9, 200.0, 352.5}) {
    for (double lat : {-90.0, -61.3, -7.5, 0.0, 33.3, 89.0, 90.0}) {
      for (double h : {0.0, 1500.0, 30000.0}) {
        in.push_back({lon, lat, h});
        ours.push_back(f.to_world({lon, lat, h}));
      }
    }
  }
  const auto proj = strielad::testing::cs2cs_3d("+proj=longlat +datum=WGS84",
                                                "+proj=geocent +datum=WGS84 +units=m", in);
  ASSERT_TRUE(proj);
  for (std::size_t k = 0; k < in.size(); ++k) {
    const Vec3 theirs{(*proj)[k][0] * 1e-3, (*proj)[k][1] * 1e-3, (*proj)[k][2] * 1e-3};
    EXPECT_LT(distance(ours[k], theirs), 1e-6)  // 1 mm
        << in[k][0] << " E " << in[k][1] << " N " << in[k][2] << " m";
  }
}

TEST(WorldFrameGlobeTest, TheVerticalIsExaggeratedAlongTheEllipsoidNormal) {
  const WorldFrame f(global_grid(), shape(FrameShape::kAuto, 10.0));
  const Vec3 ground = f.to_world({30.0, 45.0, 0.0});
  const Vec3 up = f.to_world({30.0, 45.0, 10000.0});  // 10 km at 10x: 100 km
  const Vec3 n = f.up_at(ground);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(up[c] - ground[c], 100.0 * n[c], 1e-9);
  EXPECT_NEAR(f.up_at(f.to_world({0.0, 90.0, 0.0}))[2], 1.0, 1e-12);
  EXPECT_NEAR(f.up_at(f.to_world({90.0, 0.0, 0.0}))[1], 1.0, 1e-12);
  // A steeper exaggeration moves the top, not the ground.
  const WorldFrame g = f.with_exaggeration(20.0);
  EXPECT_TRUE(g.globe());
  EXPECT_LT(distance(g.to_world({30.0, 45.0, 0.0}), ground), 1e-9);
  EXPECT_NEAR(distance(g.to_world({30.0, 45.0, 10000.0}), ground), 200.0, 1e-9);
  EXPECT_GT(g.domain().hi[2], f.domain().hi[2]);
}

TEST(WorldFrameGlobeTest, ToAxisInvertsToWorld) {
  for (const auto& m : {global_grid(), domain(-70, -30, 45, 20)}) {
    const WorldFrame f(m, shape(FrameShape::kGlobe, 10.0));
    const double lon0 = f.lon0();
    for (double dlon : {-178.0, -90.0, -1.0, 0.0, 33.0, 177.0}) {
      for (double lat : {-89.5, -45.0, 0.0, 12.5, 60.0, 89.5}) {
        for (double h : {0.0, 250.0, 12000.0, 30000.0}) {
          const Vec3 a{lon0 + dlon, lat, h};
          const Vec3 back = f.to_axis(f.to_world(a));
          EXPECT_NEAR(back[0], a[0], 1e-9) << dlon << " " << lat << " " << h;
          EXPECT_NEAR(back[1], a[1], 1e-9) << dlon << " " << lat << " " << h;
          EXPECT_NEAR(back[2], a[2], 1e-5) << dlon << " " << lat << " " << h;  // 10 um
          const Vec3 g = f.geographic_of(f.place_geographic(a[0], a[1], 5.0));
          EXPECT_NEAR(g[0], a[0], 1e-9);
          EXPECT_NEAR(g[1], a[1], 1e-9);
          EXPECT_NEAR(g[2], 5.0, 1e-7);
        }
      }
    }
  }
}

TEST(WorldFrameGlobeTest, NormalsArePerpendicularToThePlacedSurface) {
  const WorldFrame f(global_grid(), shape(FrameShape::kAuto, 10.0));
  const auto d = [&f](const Vec3& p, int axis) {
    Vec3 a = p, b = p;
    const double h = axis == 2 ? 1.0 : 1e-5;
    a[axis] -= h;
    b[axis] += h;
    const Vec3 wa = f.to_world(a), wb = f.to_world(b);
    return Vec3{(wb[0] - wa[0]) / (2 * h), (wb[1] - wa[1]) / (2 * h), (wb[2] - wa[2]) / (2 * h)};
  };
  for (const Vec3 p : {Vec3{10, 20, 500}, Vec3{200, -70, 9000}, Vec3{300, 85, 0}}) {
    // A horizontal surface's normal is the local up.
    const Vec3 up = f.normal_to_world(p, {0, 0, 1});
    const Vec3 expected = f.up_at(f.to_world(p));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(up[c], expected[c], 1e-6);
    // An oblique axis normal stays perpendicular to the tangents it was perpendicular to.
    const Vec3 n{0.3, -0.5, 0.002};
    const Vec3 t1{0.5, 0.3, 0.0}, t2{0.0, 0.002, 0.5};  // n . t = 0 in axis space
    for (const Vec3& t : {t1, t2}) {
      Vec3 wt{0, 0, 0};
      for (int axis = 0; axis < 3; ++axis) {
        const Vec3 col = d(p, axis);
        for (int c = 0; c < 3; ++c) wt[c] += col[c] * t[axis];
      }
      const Vec3 wn = f.normal_to_world(p, n);
      const double len = std::sqrt(wt[0] * wt[0] + wt[1] * wt[1] + wt[2] * wt[2]);
      EXPECT_NEAR((wn[0] * wt[0] + wn[1] * wt[1] + wn[2] * wt[2]) / len, 0.0, 1e-5);
    }
  }
}

TEST(WorldFrameGlobeTest, PlaneOnlyMapsRefuseOnTheGlobe) {
  const WorldFrame f(global_grid(), shape(FrameShape::kAuto));
  expect_error([&] { (void)f.geographic_to_world(0, 0); }, ErrorCode::kUnsupported,
               {"geographic_to_world", "globe"});
  expect_error([&] { (void)f.world_to_geographic(0, 0); }, ErrorCode::kUnsupported,
               {"world_to_geographic", "globe"});
  const auto b = f.geographic_bounds();
  EXPECT_DOUBLE_EQ(b.lon_lo, 0.0);
  EXPECT_DOUBLE_EQ(b.lon_hi, 352.5);
  EXPECT_DOUBLE_EQ(b.lat_lo, -90.0);
  EXPECT_DOUBLE_EQ(b.lat_hi, 90.0);
}

// Every node's box holds the world position of every point of its brick: the samples and
// points between them (quarter steps), at every height.
void expect_boxes_hold_their_bricks(const format::Manifest& m, double exaggeration) {
  const WorldFrame f(m, shape(FrameShape::kGlobe, exaggeration));
  const OctreeLayout layout(m.dims(), m.brick);
  const auto boxes = node_world_boxes(layout, f);
  ASSERT_EQ(boxes.size(), layout.node_count());
  const auto value = [](const std::vector<double>& v, double index) {
    const auto i = static_cast<std::size_t>(std::min(index, static_cast<double>(v.size() - 2)));
    return v[i] + (index - static_cast<double>(i)) * (v[i + 1] - v[i]);
  };
  double loosest = 0;
  for (NodeId id = 0; id < layout.node_count(); ++id) {
    const IndexBox ib = layout.fine_box(layout.key(id));
    const WorldBox& b = boxes[id];
    WorldBox tight{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
    for (double i = ib.lo[0]; i <= ib.hi[0] + 1e-9; i += 0.25) {
      for (double j = ib.lo[1]; j <= ib.hi[1] + 1e-9; j += 0.25) {
        for (double k = ib.lo[2]; k <= ib.hi[2] + 1e-9; k += 0.5) {
          const Vec3 p = f.to_world({value(m.x.values, i), value(m.y.values, j),
                                     value(m.z.values, k)});
          ASSERT_TRUE(b.contains(p)) << "node " << id << " point (" << i << ", " << j << ", "
                                     << k << ")";
          for (int c = 0; c < 3; ++c) {
            tight.lo[c] = std::min(tight.lo[c], p[c]);
            tight.hi[c] = std::max(tight.hi[c], p[c]);
          }
        }
      }
    }
    for (int c = 0; c < 3; ++c) {
      loosest = std::max(loosest, (b.hi[c] - b.lo[c]) / std::max(tight.hi[c] - tight.lo[c], 1.0));
    }
  }
  EXPECT_EQ(boxes[layout.root()], f.domain());
  // Padded, not blown up: no box more than 3 times the extent of its points.
  EXPECT_LT(loosest, 3.0);
}

TEST(WorldFrameGlobeTest, NodeBoxesHoldEveryPointOfTheirBricksOnAGlobalGrid) {
  expect_boxes_hold_their_bricks(global_grid(9, 8), 10.0);
  expect_boxes_hold_their_bricks(global_grid(9, 4), 100.0);
}

TEST(WorldFrameGlobeTest, NodeBoxesHoldEveryPointOfTheirBricksOnARegionalGrid) {
  expect_boxes_hold_their_bricks(domain(120, 40, 60, 40, 31, 23, 5, 4), 10.0);
}

}  // namespace
}  // namespace strielad::lod
