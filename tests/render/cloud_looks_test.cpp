// SPDX-License-Identifier: Apache-2.0
// The built-in looks in pixels: the default clouds let the background through a thin
// sub-volume and hide it behind a thick one (opacity from the chord, 50% after 4 km);
// the "scalar on surface" look colours a surface by an attribute through the colour
// map; its legend shows the map over the range.
#include <algorithm>
#include <cmath>
#include <string>

#include "render/colour_bar_legend.h"
#include "render/slice_drawing.h"
#include "render/surface_scalar_look.h"
#include "render/volume_shaders.h"
#include "render_fixture.h"

namespace strielad::testing {
namespace {

int brightness(const render::RgbaImage& image, std::pair<int, int> px) {
  const auto p = image.at(px.first, px.second);
  return p[0] + p[1] + p[2];
}

// The sphere store on a grid of 129 samples per axis (0.87 km apart), fine enough for
// spheres a few kilometres across.
class FineSphereTest : public RenderTest {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir();
    store_ = new std::filesystem::path(write_sphere_store(dir_->path(), 16, 129));
    context_ = render::HeadlessContext::create().release();
  }
};

// Close to sphere 1, from the south, level with its centre: the ray through the centre
// runs 2r inside a sphere of radius r.
const Vec3 kNearEye{kSphereCenter1[0], -30.0, kSphereCenter1[2]};

// The default shader with its opacity forced to 1: the colour an opaque cloud would have.
std::string opaque_default_shader() {
  std::string s = render::default_user_shader();
  const std::string body = "return 1.0 - exp(-distance * (0.693147 / kHalfOpacityKm));";
  const auto at = s.find(body);
  EXPECT_NE(at, std::string::npos) << "the default shader's alpha() changed";
  if (at != std::string::npos) s.replace(at, body.size(), "return 1.0;");
  return s;
}

TEST_F(FineSphereTest, DefaultCloudsAreTranslucentWhereThinAndOpaqueWhereThick) {
  Scene thin, thick;
  thin.subvolumes = {sphere(1, "d1", 2.0)};    // 4 km through the centre
  thick.subvolumes = {sphere(1, "d1", 15.0)};  // 30 km
  const auto first = render(thin, kNearEye, kSphereCenter1, opaque_default_shader());
  const auto centre = project(camera(kNearEye, kSphereCenter1), kSphereCenter1);
  const int opaque_thin = brightness(first.image, centre);
  const int opaque_thick =
      brightness(render(thick, kNearEye, kSphereCenter1, opaque_default_shader()).image, centre);
  ASSERT_GT(opaque_thin, 300) << "the thin sphere is not drawn";
  ASSERT_GT(opaque_thick, 300) << "the thick sphere is not drawn";
  const auto& clouds = render::default_user_shader();
  const int thin_b = brightness(render(thin, kNearEye, kSphereCenter1, clouds).image, centre);
  const int thick_b = brightness(render(thick, kNearEye, kSphereCenter1, clouds).image, centre);
  // Over a black background the pixel is the cloud's colour times its opacity:
  // 1 - 2^(-4/4) = 0.50 for 4 km, 0.99 for 30 km (50% after 1.5 km would give 0.84).
  const double thin_opacity = double(thin_b) / opaque_thin;
  const double thick_opacity = double(thick_b) / opaque_thick;
  EXPECT_GT(thin_opacity, 0.35);
  EXPECT_LT(thin_opacity, 0.65) << "a 4 km chord hides too much of the background";
  EXPECT_GT(thick_opacity, 0.97) << "a 30 km chord lets the background through";
}

// From the south, level with the sphere centres (as abuffer_pixels_test.cpp).
const Vec3 kSouthEye{5.0, -320.0, 55.0};
const Vec3 kSouthTarget{5.0, 0.0, 55.0};

TEST_F(RenderTest, ScalarLookColoursTheSurfaceByTheAttributeThroughTheMap) {
  Scene scene;
  scene.subvolumes = {sphere(1, "d1", 20.0)};
  scene.attributes = {"d1", "d2"};
  render::SurfaceScalarLook look;
  look.components = {1};  // d2: the distance to sphere 2's centre
  look.colormap = "magma";
  look.lo = 30.0;
  look.hi = 80.0;
  const auto frame = render(scene, kSouthEye, kSouthTarget, render::surface_scalar_shader(look));
  const auto cam = camera(kSouthEye, kSouthTarget);
  // Sphere 1's point nearest the eye, facing it: the normal is -y.
  const Vec3 front = add(kSphereCenter1, Vec3{0.0, -20.0, 0.0});
  const double d2 = length(sub(front, kSphereCenter2));  // 53.9
  const auto map = render::colormap_color("magma", (d2 - look.lo) / (look.hi - look.lo));
  // Lit as surface_scalar.glsl does: 80% plus 20% of the sun's cosine.
  const Vec3 sun = normalize(render::FrameInputs{}.sun_direction);
  const double light = 0.8 + 0.2 * std::max(0.0, -sun[1]);
  const auto got = frame.image.at(project(cam, front).first, project(cam, front).second);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(got[c], map[c] * light * 255.0, 8.0) << "channel " << c << " at d2 = " << d2;
  }
  // A point nearer sphere 2 (d2 about 33) is near the map's low end: darker in magma.
  const Vec3 east = add(kSphereCenter1, Vec3{18.0, -8.0, 0.0});
  const auto east_px = frame.image.at(project(cam, east).first, project(cam, east).second);
  EXPECT_LT(east_px[0] + east_px[1] + east_px[2] + 60, got[0] + got[1] + got[2]);
}

TEST(ColourBarLegend, ShowsTheMapOverTheRangeWithItsTitle) {
  render::RgbaImage image{640, 360, std::vector<std::uint8_t>(640 * 360 * 4, 90)};
  const render::ColourBarLegend legend{"wind speed (m s-1)", "viridis", 0.0, 40.0};
  render::draw_colour_bar_legend(image, legend);
  const auto bar = render::colour_bar_placement(image.width, image.height);
  ASSERT_GT(bar.width, 32);
  ASSERT_LE(bar.x + bar.width, image.width);
  for (const int i : {0, bar.width / 3, bar.width - 1}) {
    const auto want = render::colormap_color("viridis", (i + 0.5) / bar.width);
    const auto got = image.at(bar.x + i, bar.y + bar.height / 2);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c] * 255.0, 1.0) << "column " << i;
  }
  // Text: white pixels above the bar (the title) and below it (the values).
  int title = 0, values = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto p = image.at(x, y);
      if (p[0] != 255 || p[1] != 255 || p[2] != 255) continue;
      (y < bar.y ? title : values) += 1;
    }
  }
  EXPECT_GT(title, 40);
  EXPECT_GT(values, 15);
  // The rest of the image is untouched.
  EXPECT_EQ(image.at(5, 5)[0], 90);
  EXPECT_EQ(image.at(5, image.height - 5)[0], 90);
}

}  // namespace
}  // namespace strielad::testing
