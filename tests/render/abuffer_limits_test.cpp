// SPDX-License-Identifier: Apache-2.0
// What the A-buffer does at its memory bounds (docs/view.md "The A-buffer"): a pixel with
// more than K = 32 fragments keeps the nearest 32, so what is lost lies behind what is
// kept; a frame that overflows a pool at its bound is drawn again with a depth limit,
// so that the fragments dropped are the farthest, and counted. Both are measured here on nested sphere shells and on two
// spheres along the view.
#include <cmath>
#include <limits>

#include "render/png_file.h"
#include "render_fixture.h"

namespace strielad::testing {
namespace {

std::string red_shader(double alpha) {
  return "vec4 color(int id, float attributes[MAX_ATTRIBUTES], vec3 normal, vec3 sun,\n"
         "           vec3 position, vec3 view, float time) { return vec4(1, 0, 0, 1); }\n"
         "float alpha(int id, float distance) { return " +
         std::to_string(alpha) + "; }\n";
}

// Twelve shells around sphere centre 1: 2 km thick, 2 km apart (radius 1..47 km).
Scene shells() {
  Scene scene;
  for (std::uint32_t i = 0; i < 12; ++i) {
    SubVolume s;
    s.id = i + 1;
    s.name = "shell";
    const double r = 1.0 + 4.0 * i;
    s.limits.push_back(Limit{.var = "d1", .min = r, .max = r + 2.0});
    scene.subvolumes.push_back(std::move(s));
  }
  return scene;
}

class AbufferLimitsTest : public RenderTest {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir();
    // A finer grid (1.7 km between samples) so that 2 km shells are resolved.
    store_ = new std::filesystem::path(write_sphere_store(dir_->path(), 16, 65));
    context_ = render::HeadlessContext::create().release();
  }
};

const Vec3 kEye{-20.0, -330.0, 55.0};

TEST_F(AbufferLimitsTest, APixelOverKFragmentsKeepsTheNearestAndLosesLittle) {
  const auto frame = render(shells(), kEye, kSphereCenter1, red_shader(0.25));
  const auto& s = frame.stats;
  // Through the centre a ray crosses 24 shell walls: 48 fragments and more at node faces.
  EXPECT_GT(s.max_fragments_per_pixel, 32u);
  EXPECT_GT(s.truncated_pixels, 0u);
  EXPECT_EQ(s.dropped_fragments, 0u);
  // The 32 nearest hold every front wall (12 segments) and some back walls: at least
  // 1 - 0.75^12 = 96.8% of red, where all 24 walls would give 99.9%.
  const auto cam = camera(kEye, kSphereCenter1);
  const auto centre = frame.image.at(project(cam, kSphereCenter1).first,
                                     project(cam, kSphereCenter1).second);
  EXPECT_GE(centre[0], static_cast<int>(std::floor(255 * (1 - std::pow(0.75, 12)))));
  EXPECT_EQ(centre[1], 0);
  if (const char* out = std::getenv("STRIELAD_TEST_IMAGES")) {
    render::write_png(std::filesystem::path(out) / "shells.png", frame.image);
  }
  RecordProperty("max_fragments_per_pixel", static_cast<int>(s.max_fragments_per_pixel));
  RecordProperty("truncated_pixels", static_cast<int>(s.truncated_pixels));
  RecordProperty("centre_red", centre[0]);
}

// The sphere store of the pixel tests: its spheres lie in different octree nodes at
// every level below the root, so drawing nodes nearest first orders them.
class AbufferPoolTest : public RenderTest {};

TEST_F(AbufferPoolTest, AFullPoolDropsTheFarthestNodesFragmentsAndCountsThem) {
  const Vec3 east{330.0, 0.0, 55.0}, middle{5.0, 0.0, 55.0};
  // Seen from the east, sphere 2 (blue) hides sphere 1 (red) behind it. First how many
  // fragments the near sphere alone has, then both spheres unbounded.
  Scene near_only;
  near_only.subvolumes = {sphere(3, "d2", 20.0)};
  const auto alone = render(near_only, east, middle, flat_shader("return 1.0;"));
  Scene scene;
  scene.subvolumes = {sphere(1, "d1", 20.0), sphere(3, "d2", 20.0)};
  const auto full = render(scene, east, middle, flat_shader("return 1.0;"));
  ASSERT_EQ(full.stats.dropped_fragments, 0u);
  // A pool that holds the near sphere's fragments only: the bound holds, the rest is
  // counted, and the second geometry pass with a depth limit from the histogram drops
  // exactly the far sphere's: the picture is the unbounded one.
  const std::size_t capacity = std::max<std::size_t>(alone.stats.fragments, 1024);
  ASSERT_GT(full.stats.fragments, capacity);
  renderer_ = std::make_unique<render::VolumeRenderer>(render::RenderSettings{
      .max_fragment_bytes = capacity * render::kFragmentBytes,
      .background_top = {0, 0, 0},
      .background_bottom = {0, 0, 0}});
  const auto bounded = render(scene, east, middle, flat_shader("return 1.0;"));
  EXPECT_EQ(bounded.stats.fragment_capacity, capacity);
  EXPECT_EQ(bounded.stats.dropped_fragments, full.stats.fragments - capacity);
  EXPECT_EQ(bounded.stats.geometry_passes, 2);
  EXPECT_LT(bounded.stats.depth_limit_km, 340.0f);  // between the spheres' depths
  EXPECT_GT(bounded.stats.depth_limit_km, 320.0f);
  EXPECT_EQ(bounded.image.pixels, full.image.pixels);
  RecordProperty("fragments_needed", static_cast<int>(full.stats.fragments));
  RecordProperty("dropped", static_cast<int>(bounded.stats.dropped_fragments));
}

TEST_F(AbufferLimitsTest, ThePoolGrowsWithinTheFrameThatNeedsIt) {
  // First at a bound of 1024 fragments (the smallest): the frame is cut at a depth.
  renderer_->set_max_fragment_bytes(1024 * render::kFragmentBytes);
  const auto small = render(shells(), kEye, kSphereCenter1, red_shader(0.5));
  EXPECT_EQ(small.stats.fragment_capacity, 1024u);
  EXPECT_LT(small.stats.depth_limit_km, std::numeric_limits<float>::max());
  EXPECT_GT(small.stats.dropped_fragments, 0u);
  // The default bound: the same frame grows the pool and is drawn again, whole.
  renderer_->set_max_fragment_bytes(render::kDefaultMaxFragmentBytes);
  const auto frame = render(shells(), kEye, kSphereCenter1, red_shader(0.5));
  EXPECT_EQ(frame.stats.geometry_passes, 2);
  EXPECT_EQ(frame.stats.dropped_fragments, 0u);
  EXPECT_GE(frame.stats.fragment_capacity, frame.stats.fragments);
  EXPECT_EQ(frame.stats.depth_limit_km, std::numeric_limits<float>::max());
}

}  // namespace
}  // namespace strielad::testing
