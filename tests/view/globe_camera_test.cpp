// SPDX-License-Identifier: Apache-2.0
// The orbit camera on the globe (lib/view/orbit_camera.h, lib/view/globe_view.h): home
// over a chosen point or the sub-solar point, orbit about the Earth's centre, zoom that
// stays above the ground and moves towards the cursor, the tilt towards the horizon near
// the surface; and the sun's direction on the globe (lib/view/sun_direction.h).
#include <gtest/gtest.h>

#include <cmath>

#include "lod/lod_test_grids.h"
#include "lod/wgs84_globe.h"
#include "lod/world_frame.h"
#include "view/globe_view.h"
#include "view/orbit_camera.h"
#include "view/simulation_time.h"
#include "view/sun_direction.h"

namespace strielad::view {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

format::Manifest global_manifest(const std::string& time_units) {
  format::Manifest m = lod::testing::geographic_manifest(48, 25, {0.0, 10000.0, 20000.0});
  m.x.values = lod::testing::linspace(0.0, 352.5, 48);
  m.y.values = lod::testing::linspace(-90.0, 90.0, 25);
  m.time.units = time_units;
  return m;
}

lod::WorldFrame globe(const format::Manifest& m) {
  return lod::WorldFrame(m, {.vertical_exaggeration = 20.0, .shape = lod::FrameShape::kAuto});
}

// The longitude and latitude below the eye.
std::array<double, 2> sub_point(const OrbitCamera& c) {
  const Vec3 e = c.eye();
  return {std::atan2(e[1], e[0]) / kDeg, std::atan2(e[2], std::hypot(e[0], e[1])) / kDeg};
}

TEST(GlobeCameraTest, HomeLooksAtTheEarthsCentreFromAboveThePoint) {
  const auto m = global_manifest("seconds since 2024-06-21 12:00:00");
  const auto frame = globe(m);
  OrbitCamera c(frame.domain());
  c.set_globe(40.0, -20.0);
  EXPECT_NEAR(sub_point(c)[0], 40.0, 1e-9);
  EXPECT_NEAR(sub_point(c)[1], -20.0, 1e-9);
  EXPECT_NEAR(length(c.target()), 0.0, 1e-9);
  // The whole Earth in a 45-degree view.
  EXPECT_GT(std::asin(lod::kWgs84SemiMajorKm / c.distance()), 0.0);
  EXPECT_LT(std::asin(lod::kWgs84SemiMajorKm / c.distance()), 22.5 * kDeg);
  const lod::Camera cam = c.camera(1.0);
  EXPECT_NEAR(length(cam.target), 0.0, 1e-9);
  // Orbiting turns about the polar axis: the latitude stays.
  c.orbit(-30.0, 0.0);
  EXPECT_NEAR(sub_point(c)[0], 70.0, 1e-9);
  EXPECT_NEAR(sub_point(c)[1], -20.0, 1e-9);
}

TEST(GlobeCameraTest, AGlobalStoreIsSeenOverItsSubSolarPoint) {
  const auto m = global_manifest("seconds since 2024-06-21 12:00:00");
  const auto frame = globe(m);
  const auto home = globe_home_point(frame, m, 0);
  EXPECT_NEAR(home[0], 0.5, 1.0);    // 12 UTC: near Greenwich
  EXPECT_NEAR(home[1], 23.44, 0.1);  // the June solstice
  const OrbitCamera c = home_orbit_camera(frame, m, 0);
  EXPECT_TRUE(c.globe());
  EXPECT_NEAR(sub_point(c)[0], home[0], 1e-9);
  // The sun's direction is the sub-solar point's up (its ellipsoid normal: the sun in
  // the zenith there), and from there it stands overhead.
  const auto sun = sun_at_step(frame, m, 0);
  ASSERT_TRUE(sun);
  const Vec3 up = lod::local_axes(home[0], home[1]).up;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(sun->direction[c], up[c], 1e-12);
  EXPECT_NEAR(sun->position.elevation_deg, 90.0, 0.5);
  // A regional domain on the plane keeps the plane's camera.
  format::Manifest small = lod::testing::geographic_manifest(5, 5, {0.0, 1000.0});
  const lod::WorldFrame plane(small, {.shape = lod::FrameShape::kAuto});
  EXPECT_FALSE(plane.globe());
  EXPECT_FALSE(home_orbit_camera(plane, small, 0).globe());
}

TEST(GlobeCameraTest, ZoomStaysAboveTheGroundAndTiltsTowardsTheHorizon) {
  const auto m = global_manifest("seconds since 2024-06-21 12:00:00");
  OrbitCamera c(globe(m).domain());
  c.set_globe(10.0, 45.0);
  const double a = lod::kWgs84SemiMajorKm;
  // Far out the view looks at the centre.
  lod::Camera cam = c.camera(1.0);
  EXPECT_NEAR(length(cam.target), 0.0, 1e-6);
  for (int i = 0; i < 200; ++i) c.zoom(0.5);
  EXPECT_GE(c.distance(), a + 10.0 - 1e-9);
  // At the ground the view looks 70 degrees away from straight down, northwards.
  cam = c.camera(1.0);
  const Vec3 look = sub(cam.target, cam.eye);
  const Vec3 down = scale(cam.eye, -1.0 / length(cam.eye));
  const double angle = std::acos(dot(look, down) / length(look)) / kDeg;
  EXPECT_NEAR(angle, 70.0, 0.5);
  EXPECT_GT(look[2], 0.0);  // towards the north pole from 45 N
  EXPECT_LT(c.drag_scale(), 0.01);
}

TEST(GlobeCameraTest, ZoomMovesTowardsTheCursorAndPanTurnsTheEarth) {
  const auto m = global_manifest("seconds since 2024-06-21 12:00:00");
  OrbitCamera c(globe(m).domain());
  c.set_globe(0.0, 0.0);
  c.zoom_at(0.5, 0.3, 0.0);  // the cursor right of the centre: east
  EXPECT_GT(sub_point(c)[0], 1.0);
  EXPECT_NEAR(sub_point(c)[1], 0.0, 1e-9);
  c.set_globe(0.0, 0.0);
  c.zoom_at(0.5, 0.0, 0.3);  // above the centre: north
  EXPECT_GT(sub_point(c)[1], 1.0);
  c.set_globe(0.0, 0.0);
  c.pan(0.1, 0.0);
  EXPECT_GT(sub_point(c)[0], 0.5);
  EXPECT_NEAR(length(c.target()), 0.0, 1e-9);  // still about the centre
  c.set_globe(0.0, 0.0);
  c.fly(1000.0, 0.0, 0.0);  // forward: north
  EXPECT_GT(sub_point(c)[1], 0.0);
}

}  // namespace
}  // namespace strielad::view
