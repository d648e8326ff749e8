// SPDX-License-Identifier: Apache-2.0
// Headless renders of sphere sub-volumes checked pixel by pixel: coverage, the colour
// of each sub-volume id, a nested sub-volume seen through its outer one, the order of
// two sub-volumes along the view, and opacity from the distance travelled inside
// across node faces.
#include <cmath>

#include "render/png_file.h"
#include "render_fixture.h"

namespace strielad::testing {
namespace {

using Rgb = std::array<int, 3>;

Rgb rgb_at(const render::RgbaImage& image, std::pair<int, int> px) {
  const auto p = image.at(px.first, px.second);
  return {p[0], p[1], p[2]};
}

void expect_rgb_near(const Rgb& actual, const Rgb& expected, int tolerance, const char* what) {
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(actual[c], expected[c], tolerance)
        << what << ": channel " << c << " is " << actual[c] << ", expected " << expected[c];
  }
}

// The side view: from the south (-y), level with the sphere centres.
const Vec3 kSouthEye{5.0, -320.0, 55.0};
const Vec3 kSouthTarget{5.0, 0.0, 55.0};

TEST_F(RenderTest, AnOpaqueSphereCoversItsProjectedDisc) {
  Scene scene;
  scene.subvolumes = {sphere(1, "d1", 30.0)};
  const auto frame = render(scene, kSouthEye, kSouthTarget, flat_shader("return 1.0;"));
  EXPECT_EQ(frame.stats.dropped_fragments, 0u);
  const auto cam = camera(kSouthEye, kSouthTarget);
  expect_rgb_near(rgb_at(frame.image, project(cam, kSphereCenter1)), {255, 0, 0}, 2, "centre");
  expect_rgb_near(rgb_at(frame.image, {2, 2}), {0, 0, 0}, 0, "corner");
  // Red pixels against the disc the sphere projects to (radius from the view angle).
  const double distance = length(sub(kSphereCenter1, kSouthEye));
  const double angular_radius = std::asin(30.0 / distance);
  const double radius_px = std::tan(angular_radius) / std::tan(22.5 * M_PI / 180) * kSize / 2;
  int red = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) red += frame.image.at(x, y)[0] > 128 ? 1 : 0;
  const double expected = M_PI * radius_px * radius_px;
  EXPECT_NEAR(red, expected, 0.08 * expected) << "disc of radius " << radius_px << " px";
}

TEST_F(RenderTest, EachSubVolumeIdGetsItsColour) {
  Scene scene;
  scene.subvolumes = {sphere(1, "d1", 20.0), sphere(3, "d2", 15.0)};
  const auto frame = render(scene, kSouthEye, kSouthTarget, flat_shader("return 1.0;"));
  const auto cam = camera(kSouthEye, kSouthTarget);
  expect_rgb_near(rgb_at(frame.image, project(cam, kSphereCenter1)), {255, 0, 0}, 2, "id 1");
  expect_rgb_near(rgb_at(frame.image, project(cam, kSphereCenter2)), {0, 0, 255}, 2, "id 3");
  // Between the spheres: background.
  const Vec3 between{7.0, 0.0, 55.0};
  expect_rgb_near(rgb_at(frame.image, project(cam, between)), {0, 0, 0}, 0, "between");
}

TEST_F(RenderTest, ANestedSubVolumeShowsThroughItsOuterOne) {
  Scene scene;
  scene.subvolumes = {sphere(1, "d1", 30.0), sphere(2, "d1", 12.0)};
  const auto frame = render(scene, kSouthEye, kSouthTarget,
                            flat_shader("return id == 1 ? 0.5 : 1.0;"));
  const auto cam = camera(kSouthEye, kSouthTarget);
  // Through the centre: the outer shell (half opaque) in front of the opaque core.
  expect_rgb_near(rgb_at(frame.image, project(cam, kSphereCenter1)), {128, 127, 0}, 4,
                  "core through shell");
  // 20 km off the centre: only the shell.
  const Vec3 ring{kSphereCenter1[0], 0.0, kSphereCenter1[2] + 20.0};
  expect_rgb_near(rgb_at(frame.image, project(cam, ring)), {128, 0, 0}, 4, "shell only");
}

TEST_F(RenderTest, TheNearerOfTwoSubVolumesDominates) {
  Scene scene;
  scene.subvolumes = {sphere(1, "d1", 20.0), sphere(3, "d2", 20.0)};
  const auto shader = flat_shader("return 0.6;");
  // Along the line through both centres, from the east: sphere 2 (blue) is in front.
  const Vec3 east{330.0, 0.0, 55.0}, west{-320.0, 0.0, 55.0}, middle{5.0, 0.0, 55.0};
  auto frame = render(scene, east, middle, shader);
  auto cam = camera(east, middle);
  // 0.6 of the front colour, 0.4 * 0.6 of the one behind.
  expect_rgb_near(rgb_at(frame.image, project(cam, middle)), {61, 0, 153}, 4, "from the east");
  frame = render(scene, west, middle, shader);
  cam = camera(west, middle);
  expect_rgb_near(rgb_at(frame.image, project(cam, middle)), {153, 0, 61}, 4, "from the west");
}

TEST_F(RenderTest, OpacityFollowsTheWholeDistanceInsideAcrossNodeFaces) {
  // Linear in distance, so a chord split at node faces and composited in pieces would
  // come out darker: 60 km in one piece is 0.6, two 30 km pieces 0.51.
  Scene scene;
  scene.subvolumes = {sphere(1, "d1", 30.0)};
  const auto frame =
      render(scene, kSouthEye, kSouthTarget, flat_shader("return min(distance / 100.0, 1.0);"));
  ASSERT_GT(frame.cut_nodes, 1u);
  const auto cam = camera(kSouthEye, kSouthTarget);
  // The chord through the centre is 60 km of horizontal (true-scale) distance.
  const auto centre = rgb_at(frame.image, project(cam, kSphereCenter1));
  EXPECT_NEAR(centre[0], 153, 8);
  // A vertical chord is travelled at true scale too: seen from above, the 60 km of
  // exaggerated height are 6 km of air.
  const Vec3 above{kSphereCenter1[0], 0.1, 400.0};
  const auto top = render(scene, above, kSphereCenter1, flat_shader("return min(distance / 10.0, 1.0);"));
  const auto top_cam = camera(above, kSphereCenter1);
  EXPECT_NEAR(rgb_at(top.image, project(top_cam, kSphereCenter1))[0], 153, 8);
  if (const char* out = std::getenv("STRIELAD_TEST_IMAGES")) {
    render::write_png(std::filesystem::path(out) / "sphere_side.png", frame.image);
    render::write_png(std::filesystem::path(out) / "sphere_top.png", top.image);
  }
}

}  // namespace
}  // namespace strielad::testing
