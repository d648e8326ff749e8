// SPDX-License-Identifier: Apache-2.0
// Shared set-up of the render tests: a headless OpenGL context, the sphere store
// (support/sphere_store.h) served in-process, and a helper that renders a scene from a
// camera once its cut is complete (optionally with meshes moved by displacement maps).
#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "lod/camera.h"
#include "render/complete_frame.h"
#include "render/headless_context.h"
#include "render/offscreen_target.h"
#include "render/volume_renderer.h"
#include "scene/scene.h"
#include "support/sphere_store.h"
#include "support/temp_dir.h"
#include "view/local_server.h"
#include "view/view_controller.h"
#include "view/view_link.h"

namespace strielad::testing {

// Flat colours: id 1 red, id 2 green, id 3 blue; the opacity is given per test.
inline std::string flat_shader(const std::string& alpha_body) {
  return "vec4 color(int id, float attributes[MAX_ATTRIBUTES], vec3 normal, vec3 sun,\n"
         "           vec3 position, vec3 view, float time) {\n"
         "  return id == 1 ? vec4(1, 0, 0, 1) : id == 2 ? vec4(0, 1, 0, 1) : vec4(0, 0, 1, 1);\n"
         "}\n"
         "float alpha(int id, float distance) {\n" +
         alpha_body + "\n}\n";
}

inline SubVolume sphere(std::uint32_t id, const std::string& var, double radius) {
  SubVolume s;
  s.id = id;
  s.name = var;
  s.limits.push_back(Limit{.var = var, .min = std::nullopt, .max = radius});
  return s;
}

class RenderTest : public ::testing::Test {
 protected:
  static constexpr int kSize = 128;

  static void SetUpTestSuite() {
    dir_ = new TempDir();
    store_ = new std::filesystem::path(write_sphere_store(dir_->path()));
    context_ = render::HeadlessContext::create().release();
  }
  static void TearDownTestSuite() {
    delete context_;
    delete store_;
    delete dir_;
  }

  void SetUp() override {
    connection_ = view::open_local_store(*store_, view::LocalServerOptions{.threads = 2});
    link_ = std::make_unique<view::ViewLink>(std::move(connection_.client));
    render::RenderSettings settings;
    settings.background_top = settings.background_bottom = {0, 0, 0};
    renderer_ = std::make_unique<render::VolumeRenderer>(settings);
    target_ = std::make_unique<render::OffscreenTarget>(kSize, kSize);
  }
  void TearDown() override {
    controller_.reset();
    link_.reset();
    connection_.server.reset();
  }

  lod::Camera camera(const Vec3& eye, const Vec3& target) const {
    return lod::look_at(eye, target, 45.0, 1.0, controller_->frame().domain());
  }

  // Renders `scene` seen from `eye` towards `target` with `shader`.
  render::CompleteFrame render(const Scene& scene, const Vec3& eye, const Vec3& target,
                               const std::string& shader,
                               const std::vector<render::MeshMotion>& motions = {}) {
    if (!controller_) {
      controller_ = std::make_unique<view::ViewController>(*link_, scene);
    } else {
      controller_->set_scene(scene);
    }
    std::vector<std::uint32_t> ids;
    for (const auto& s : scene.subvolumes) ids.push_back(s.id);
    EXPECT_TRUE(renderer_->set_scene_layout(ids, scene.attributes).ok);
    const auto update = renderer_->set_user_shader(shader, "test.glsl");
    EXPECT_TRUE(update.ok) << update.error;
    const auto cam = camera(eye, target);
    auto inputs = render::frame_inputs(*controller_, cam);
    inputs.motions = motions;
    return render::render_complete_frame(*controller_, *renderer_, *target_, inputs);
  }

  // Pixel (column, row from the top) where a world point appears.
  static std::pair<int, int> project(const lod::Camera& cam, const Vec3& p) {
    const auto clip = lod::to_clip(lod::multiply(lod::projection_matrix(cam), lod::view_matrix(cam)), p);
    const double x = (clip[0] / clip[3] + 1) / 2 * kSize;
    const double y = (1 - clip[1] / clip[3]) / 2 * kSize;
    return {static_cast<int>(x), static_cast<int>(y)};
  }

  static inline TempDir* dir_ = nullptr;
  static inline std::filesystem::path* store_ = nullptr;
  static inline render::HeadlessContext* context_ = nullptr;
  view::LocalConnection connection_;
  std::unique_ptr<view::ViewLink> link_;
  std::unique_ptr<view::ViewController> controller_;
  std::unique_ptr<render::VolumeRenderer> renderer_;
  std::unique_ptr<render::OffscreenTarget> target_;
};

}  // namespace strielad::testing
