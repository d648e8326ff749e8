// SPDX-License-Identifier: Apache-2.0
// Meshes moved with the wind on the GPU (render/mesh_motion.h): a step's meshes drawn
// with a displacement map of 10 km east at its end land where the next step's meshes
// are (the sphere store moves its spheres 10 km east per step), half-way at half the
// time, and meshes of other steps do not move.
#include <cmath>

#include "render_fixture.h"

namespace strielad::testing {
namespace {

const Vec3 kSouthEye{5.0, -320.0, 55.0};
const Vec3 kSouthTarget{5.0, 0.0, 55.0};

// Moves everything by `east_km` over 600 s (the sphere store's step), linearly.
std::shared_ptr<const view::DisplacementMap> eastward_map(std::uint32_t step,
                                                          const lod::WorldBox& box,
                                                          double east_km) {
  auto map = std::make_shared<view::DisplacementMap>();
  map->step = step;
  map->seconds = 600;
  map->box = box;
  map->lattice = {2, 2, 2};
  map->keyframes = 3;
  map->displacement.assign(map->points() * 3 * map->keyframes, 0.0f);
  for (std::size_t k = 0; k < map->keyframes; ++k) {
    for (std::size_t p = 0; p < map->points(); ++p) {
      map->displacement[(k * map->points() + p) * 3] = static_cast<float>(east_km * k / 2.0);
    }
  }
  return map;
}

struct RedPixels {
  int count = 0;
  double mean_column = 0;
};

RedPixels red_pixels(const render::RgbaImage& image) {
  RedPixels r;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (image.at(x, y)[0] > 128) {
        ++r.count;
        r.mean_column += x;
      }
    }
  }
  if (r.count > 0) r.mean_column /= r.count;
  return r;
}

TEST_F(RenderTest, MeshesMoveWithTheirStepsDisplacementMap) {
  Scene scene;
  scene.subvolumes = {sphere(1, "d1", 20.0)};
  const auto shader = flat_shader("return 1.0;");
  scene.time = 0;
  const auto still = render(scene, kSouthEye, kSouthTarget, shader);
  const auto box = link_->placer().frame().domain();
  const auto map = eastward_map(0, box, kSphereStepShiftKm);
  const auto moved = render(scene, kSouthEye, kSouthTarget, shader, {{map, 600.0}});
  const auto half = render(scene, kSouthEye, kSouthTarget, shader, {{map, 300.0}});
  const auto other_step = render(scene, kSouthEye, kSouthTarget, shader,
                                 {{eastward_map(1, box, 40.0), 600.0}});
  EXPECT_EQ(moved.stats.nodes_moved, moved.stats.nodes_drawn);
  EXPECT_EQ(other_step.stats.nodes_moved, 0u);
  scene.time = 1;
  const auto next = render(scene, kSouthEye, kSouthTarget, shader);

  const RedPixels a = red_pixels(still.image), b = red_pixels(moved.image),
                  c = red_pixels(half.image), d = red_pixels(next.image),
                  e = red_pixels(other_step.image);
  ASSERT_GT(a.count, 200);  // a disc about 10 px in radius
  const auto cam = camera(kSouthEye, kSouthTarget);
  const double shift_px = project(cam, add(kSphereCenter1, {kSphereStepShiftKm, 0, 0})).first -
                          project(cam, kSphereCenter1).first;
  ASSERT_GT(shift_px, 2.0);
  EXPECT_NEAR(b.mean_column - a.mean_column, shift_px, 1.0);
  EXPECT_NEAR(c.mean_column - a.mean_column, shift_px / 2, 1.0);
  EXPECT_NEAR(b.mean_column, d.mean_column, 0.5);  // where the next step's sphere is
  EXPECT_NEAR(b.count, d.count, 0.03 * d.count);
  EXPECT_EQ(e.count, a.count);  // a map of another step moves nothing
  EXPECT_DOUBLE_EQ(e.mean_column, a.mean_column);
  // Pixel by pixel, the moved step-0 sphere and the step-1 sphere differ only at edges.
  int differing = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      differing += (moved.image.at(x, y)[0] > 128) != (next.image.at(x, y)[0] > 128) ? 1 : 0;
    }
  }
  EXPECT_LT(differing, 0.05 * d.count);
}

}  // namespace
}  // namespace strielad::testing
