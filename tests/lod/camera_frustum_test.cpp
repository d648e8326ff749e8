// SPDX-License-Identifier: Apache-2.0
// Cameras (lib/lod/camera.h) and their frustum (lib/lod/frustum.h): the OpenGL
// matrices, the planes agreeing with them, the conservative box test, and validation.
#include "lod/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "lod/frustum.h"
#include "support/expect_error.h"

namespace strielad::lod {
namespace {

using strielad::testing::expect_error;

Camera oblique_camera() {
  Camera c;
  c.eye = {10, -300, 120};
  c.target = {-20, 40, 0};
  c.fov_y_deg = 45;
  c.aspect = 16.0 / 9.0;
  c.near_km = 0.5;
  c.far_km = 2000;
  return c;
}

TEST(CameraFrustumTest, ViewMatrixPutsTheEyeAtTheOriginLookingDownMinusZ) {
  const Camera c = oblique_camera();
  const Mat4 v = view_matrix(c);
  const auto eye = to_clip(v, c.eye);
  EXPECT_NEAR(eye[0], 0, 1e-3);
  EXPECT_NEAR(eye[1], 0, 1e-3);
  EXPECT_NEAR(eye[2], 0, 1e-3);
  EXPECT_DOUBLE_EQ(eye[3], 1);
  const auto target = to_clip(v, c.target);
  const double d = length(sub(c.target, c.eye));
  EXPECT_NEAR(target[0], 0, 1e-3);
  EXPECT_NEAR(target[1], 0, 1e-3);
  EXPECT_NEAR(target[2], -d, 1e-3 * d);
  // World up (+z) appears as up (+y) on screen.
  const auto above = to_clip(v, add(c.target, Vec3{0, 0, 10}));
  EXPECT_GT(above[1], 1.0);
}

TEST(CameraFrustumTest, ProjectionMapsNearAndFarToTheClipRange) {
  const Camera c = oblique_camera();
  const Mat4 vp = multiply(projection_matrix(c), view_matrix(c));
  const Vec3 f = normalize(sub(c.target, c.eye));
  const auto near = to_clip(vp, add(c.eye, scale(f, c.near_km)));
  const auto far = to_clip(vp, add(c.eye, scale(f, c.far_km)));
  EXPECT_NEAR(near[2] / near[3], -1.0, 1e-3);
  EXPECT_NEAR(far[2] / far[3], 1.0, 1e-3);
}

TEST(CameraFrustumTest, FrustumPlanesAgreeWithTheMatrices) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  int checked = 0, inside = 0;
  for (int cam = 0; cam < 20; ++cam) {
    Camera c;
    c.eye = {400 * u(rng), 400 * u(rng), 200 + 100 * u(rng)};
    c.target = {100 * u(rng), 100 * u(rng), 10 * u(rng)};
    c.fov_y_deg = 30 + 60 * (u(rng) + 1) / 2;
    c.aspect = 0.5 + (u(rng) + 1);
    c.near_km = 1;
    c.far_km = 1500;
    validate_camera(c);
    const Frustum fr = view_frustum(c);
    const Mat4 vp = multiply(projection_matrix(c), view_matrix(c));
    for (int i = 0; i < 2000; ++i) {
      const Vec3 p{800 * u(rng), 800 * u(rng), 400 * u(rng)};
      const auto clip = to_clip(vp, p);
      if (clip[3] <= 0) {
        EXPECT_FALSE(fr.contains(p));
        continue;
      }
      double margin = 1e9;
      bool in = true;
      for (int a = 0; a < 3; ++a) {
        const double ndc = clip[a] / clip[3];
        margin = std::min(margin, std::fabs(std::fabs(ndc) - 1));
        in = in && std::fabs(ndc) <= 1;
      }
      if (margin < 1e-3) continue;  // too close to a plane for float matrices
      EXPECT_EQ(fr.contains(p), in) << "camera " << cam << " point " << i;
      ++checked;
      inside += in;
    }
  }
  EXPECT_GT(checked, 20000);
  EXPECT_GT(inside, 1000);
}

TEST(CameraFrustumTest, BoxTestNeverDropsAVisibleBox) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  const Camera c = oblique_camera();
  const Frustum fr = view_frustum(c);
  int dropped = 0;
  for (int i = 0; i < 5000; ++i) {
    WorldBox b;
    for (int a = 0; a < 3; ++a) {
      const double centre = 700 * u(rng), half = 60 * (u(rng) + 1);
      b.lo[a] = centre - half;
      b.hi[a] = centre + half;
    }
    bool any_inside = false;
    for (int x = 0; x <= 6 && !any_inside; ++x)
      for (int y = 0; y <= 6 && !any_inside; ++y)
        for (int z = 0; z <= 6 && !any_inside; ++z) {
          const Vec3 p{b.lo[0] + (b.hi[0] - b.lo[0]) * x / 6, b.lo[1] + (b.hi[1] - b.lo[1]) * y / 6,
                       b.lo[2] + (b.hi[2] - b.lo[2]) * z / 6};
          any_inside = fr.contains(p);
        }
    if (any_inside) {
      EXPECT_TRUE(fr.may_intersect(b)) << i;
    }
    dropped += !fr.may_intersect(b);
  }
  EXPECT_GT(dropped, 1000);  // the test does cull
  // A box containing the eye is kept; one wholly behind it is not.
  EXPECT_TRUE(fr.may_intersect(WorldBox{sub(c.eye, {1, 1, 1}), add(c.eye, {1, 1, 1})}));
  const Vec3 behind = sub(c.eye, scale(normalize(sub(c.target, c.eye)), 50));
  EXPECT_FALSE(fr.may_intersect(WorldBox{sub(behind, {5, 5, 5}), add(behind, {5, 5, 5})}));
  // Beyond the far plane.
  const Vec3 beyond = add(c.eye, scale(normalize(sub(c.target, c.eye)), 2100));
  EXPECT_FALSE(fr.may_intersect(WorldBox{sub(beyond, {5, 5, 5}), add(beyond, {5, 5, 5})}));
}

TEST(CameraFrustumTest, ValidationNamesTheBadField) {
  auto bad = [](auto change, std::string_view part) {
    Camera c = oblique_camera();
    change(c);
    expect_error([&] { validate_camera(c); }, ErrorCode::kInvalidArgument, {part});
  };
  bad([](Camera& c) { c.target = c.eye; }, "eye and target");
  bad([](Camera& c) { c.eye[1] = NAN; }, "eye");
  bad([](Camera& c) { c.up = {0, 0, 0}; }, "up");
  bad([](Camera& c) { c.up = sub(c.target, c.eye); }, "parallel");
  bad([](Camera& c) { c.fov_y_deg = 0; }, "fov");
  bad([](Camera& c) { c.fov_y_deg = 180; }, "fov");
  bad([](Camera& c) { c.aspect = 0; }, "aspect");
  bad([](Camera& c) { c.near_km = 0; }, "near");
  bad([](Camera& c) { c.far_km = c.near_km; }, "far");
  bad([](Camera& c) { c.far_km = INFINITY; }, "far");
  validate_camera(oblique_camera());
}

TEST(CameraFrustumTest, LookAtPicksAnUpAndFitsTheScene) {
  const WorldBox scene{{-350, -390, 0}, {350, 390, 210}};
  // Straight down: +z would be parallel to the view, so north (+y) is up.
  EXPECT_EQ(default_up({0, 0, 1000}, {0, 0, 0}), (Vec3{0, 1, 0}));
  EXPECT_EQ(default_up({0, -100, 100}, {0, 0, 0}), (Vec3{0, 0, 1}));
  const Camera down = look_at({0, 0, 1000}, {0, 0, 0}, 45, 1.5, scene);
  validate_camera(down);
  const Camera c = look_at({0, -900, 300}, {0, 0, 0}, 45, 1.5, scene);
  const Frustum fr = view_frustum(c);
  // Nothing of the scene lies beyond the far plane.
  for (int i = 0; i < 8; ++i) {
    const Vec3 corner{(i & 1) ? scene.hi[0] : scene.lo[0], (i & 2) ? scene.hi[1] : scene.lo[1],
                      (i & 4) ? scene.hi[2] : scene.lo[2]};
    EXPECT_GE(fr.planes[5].distance(corner), 0) << i;
  }
  EXPECT_GT(c.near_km, 0);
  EXPECT_LT(c.near_km, 1.0);
  expect_error([&] { look_at({1, 2, 3}, {1, 2, 3}, 45, 1, scene); }, ErrorCode::kInvalidArgument,
               {"eye and target"});
}

}  // namespace
}  // namespace strielad::lod
