// SPDX-License-Identifier: Apache-2.0
// Sub-volume colours in pixels (lib/view/subvolume_palette.h): the built-in shader draws
// two sub-volumes in colours of different hue whatever their ids, and subvolume_color(id)
// gives a user shader the palette colour of the sub-volume's slot, up to the last of the
// viewer's 32 slots.
#include <cmath>

#include "render/volume_shaders.h"
#include "render_fixture.h"
#include "view/subvolume_palette.h"

namespace strielad::testing {
namespace {

using Rgb = std::array<int, 3>;

Rgb rgb_at(const render::RgbaImage& image, std::pair<int, int> px) {
  const auto p = image.at(px.first, px.second);
  return {p[0], p[1], p[2]};
}

// Chromaticity: the colour with its brightness divided out, so that the same colour
// lit differently compares equal.
std::array<double, 3> chromaticity(const Rgb& c) {
  const double sum = std::max(c[0] + c[1] + c[2], 1);
  return {c[0] / sum, c[1] / sum, c[2] / sum};
}

double chromaticity_distance(const Rgb& a, const Rgb& b) {
  const auto ca = chromaticity(a), cb = chromaticity(b);
  return std::hypot(ca[0] - cb[0], ca[1] - cb[1], ca[2] - cb[2]);
}

const Vec3 kSouthEye{5.0, -320.0, 55.0};
const Vec3 kSouthTarget{5.0, 0.0, 55.0};

// Ids 2 and 3 (neither is 1): the built-in shader once drew every id but 1 in the same
// grey. It tints white with 40% of the palette colour (pale clouds), so the two differ
// less in hue than the palette's own colours: white against pale sky blue is 0.065
// apart in chromaticity, the same colour 0.
TEST_F(RenderTest, DefaultShaderGivesEverySubVolumeItsOwnColour) {
  Scene scene;
  scene.subvolumes = {sphere(2, "d1", 20.0), sphere(3, "d2", 15.0)};
  const auto frame = render(scene, kSouthEye, kSouthTarget, render::default_user_shader());
  const auto cam = camera(kSouthEye, kSouthTarget);
  const Rgb a = rgb_at(frame.image, project(cam, kSphereCenter1));
  const Rgb b = rgb_at(frame.image, project(cam, kSphereCenter2));
  EXPECT_GT(a[0] + a[1] + a[2], 150) << "sphere 1 not drawn";
  EXPECT_GT(b[0] + b[1] + b[2], 150) << "sphere 2 not drawn";
  EXPECT_GT(chromaticity_distance(a, b), 0.04)
      << "sphere 1 " << a[0] << "," << a[1] << "," << a[2] << "; sphere 2 " << b[0] << ","
      << b[1] << "," << b[2];
}

// A scene of 32 sub-volumes whose last two are the spheres: slots 30 and 31.
TEST_F(RenderTest, SubvolumeColorGivesThePaletteColourOfTheSlot) {
  Scene scene;
  for (std::uint32_t id = 1; id <= 30; ++id) scene.subvolumes.push_back(sphere(id, "d1", 0.001));
  scene.subvolumes.push_back(sphere(77, "d1", 20.0));
  scene.subvolumes.push_back(sphere(40, "d2", 15.0));
  const std::string shader =
      "vec4 color(int id, float attributes[MAX_ATTRIBUTES], vec3 normal, vec3 sun,\n"
      "           vec3 position, vec3 view, float time) {\n"
      "  return vec4(subvolume_color(id), 1.0);\n"
      "}\n"
      "float alpha(int id, float distance) { return 1.0; }\n";
  const auto frame = render(scene, kSouthEye, kSouthTarget, shader);
  const auto cam = camera(kSouthEye, kSouthTarget);
  for (const auto& [center, slot] : {std::pair{kSphereCenter1, 30}, std::pair{kSphereCenter2, 31}}) {
    const Rgb got = rgb_at(frame.image, project(cam, center));
    const auto want = view::kSubVolumePalette[slot];
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(got[c], std::lround(want[c] * 255), 2) << "slot " << slot << " channel " << c;
    }
  }
}

}  // namespace
}  // namespace strielad::testing
