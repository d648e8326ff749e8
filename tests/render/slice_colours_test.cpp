// SPDX-License-Identifier: Apache-2.0
// Slices in the picture (render/slice_drawing.h through the whole viewer path: scene,
// server, NodeResult slices, geometry, upload, drawing): a height plane through the
// centre of sphere 1, coloured by the distance to that centre over [0, 60] km, shows the
// colour map's low end where the distance is 0 and its high end 60 km away; a slice
// hides the sub-volume behind it and not the one in front of it.
#include "render/slice_drawing.h"
#include "render_fixture.h"

namespace strielad::testing {
namespace {

Slice height_slice(double metres, const std::string& colormap) {
  Slice s;
  s.id = 1;
  s.axis = "height";
  s.value = metres;
  s.var = "d1";
  s.colormap = colormap;
  s.range = AxisRange{0.0, 60.0};
  return s;
}

// The colour map's colour at some t within 0.05 of `t`, lit between 0.8 and 1, within 8
// levels per channel (the pixel centre is not exactly at the point projected, and the
// map is a 256-texel texture filtered linearly).
bool shows(const std::array<std::uint8_t, 4>& p, const std::string& map, double t) {
  for (double u = t - 0.05; u <= t + 0.05; u += 0.005) {
    const auto c = render::colormap_color(map, u);
    bool all = true;
    for (int k = 0; k < 3; ++k) {
      all = all && p[k] >= 0.8 * 255 * c[k] - 8 && p[k] <= 255 * c[k] + 8;
    }
    if (all) return true;
  }
  return false;
}

TEST_F(RenderTest, SliceShowsTheColourMapOverItsRange) {
  Scene scene;
  scene.subvolumes = {sphere(2, "d2", 1.0)};
  scene.slices = {height_slice(5500.0, "viridis")};
  const auto frame = render(scene, {0.0, -1.0, 400.0}, {0.0, 0.0, 55.0}, flat_shader("return 1.0;"));
  const auto cam = camera({0.0, -1.0, 400.0}, {0.0, 0.0, 55.0});
  const auto [cx, cy] = project(cam, kSphereCenter1);
  const auto [fx, fy] = project(cam, {kSphereCenter1[0] + 60.0, 0.0, 55.0});
  EXPECT_TRUE(shows(frame.image.at(cx, cy), "viridis", 0.0))
      << int(frame.image.at(cx, cy)[0]) << "," << int(frame.image.at(cx, cy)[1]) << ","
      << int(frame.image.at(cx, cy)[2]);
  EXPECT_TRUE(shows(frame.image.at(fx, fy), "viridis", 1.0))
      << int(frame.image.at(fx, fy)[0]) << "," << int(frame.image.at(fx, fy)[1]) << ","
      << int(frame.image.at(fx, fy)[2]);
  // Half way: the map's middle.
  const auto [mx, my] = project(cam, {kSphereCenter1[0] + 30.0, 0.0, 55.0});
  EXPECT_TRUE(shows(frame.image.at(mx, my), "viridis", 0.5));
}

TEST_F(RenderTest, SliceHidesWhatIsBehindIt) {
  // Sphere 1 (red) straddles the plane at 5.5 km: seen from above, the slice covers
  // its lower half; from below... the camera stays above, so a plane above the sphere
  // hides it and a plane below it does not.
  Scene scene;
  scene.subvolumes = {sphere(1, "d1", 15.0)};
  const auto shader = flat_shader("return 1.0;");
  const Vec3 eye{-20.0, -1.0, 400.0}, target{-20.0, 0.0, 55.0};
  scene.slices = {height_slice(9000.0, "greys")};  // 90 km drawn: above the sphere
  const auto above = render(scene, eye, target, shader);
  scene.slices = {height_slice(1000.0, "greys")};  // 10 km drawn: below it
  const auto below = render(scene, eye, target, shader);
  const auto cam = camera(eye, target);
  const auto [cx, cy] = project(cam, kSphereCenter1);
  const auto red = [](const std::array<std::uint8_t, 4>& p) { return p[0] > 150 && p[1] < 60 && p[2] < 60; };
  EXPECT_FALSE(red(above.image.at(cx, cy)));
  EXPECT_TRUE(red(below.image.at(cx, cy)));
}

}  // namespace
}  // namespace strielad::testing
