// SPDX-License-Identifier: Apache-2.0
// The level-of-detail cross-fade (render/lod_fade.h): its weight over time, the blend's
// arithmetic, and headless renders of a cut that changes under a fixed camera (a coarse
// cut replaced by the leaves): with fading the change spreads over frames, each at most
// about half of the pop; with fading off the images are those of a plain render.
#include <algorithm>
#include <cmath>
#include <set>

#include "render/lod_fade.h"
#include "render_fixture.h"

namespace strielad::testing {
namespace {

// The largest difference of any channel of any pixel.
int max_change(const render::RgbaImage& a, const render::RgbaImage& b) {
  EXPECT_EQ(a.pixels.size(), b.pixels.size());
  int most = 0;
  for (std::size_t i = 0; i < std::min(a.pixels.size(), b.pixels.size()); ++i) {
    most = std::max(most, std::abs(int(a.pixels[i]) - int(b.pixels[i])));
  }
  return most;
}

TEST(LodFadeSchedule, WeightGoesLinearlyFromZeroToOneOverTheFadeTime) {
  render::LodFadeSchedule s(300);
  EXPECT_TRUE(s.enabled());
  EXPECT_FALSE(s.running());
  EXPECT_EQ(s.weight(), 1.0);  // idle: the current set alone
  s.start();
  EXPECT_TRUE(s.running());
  EXPECT_EQ(s.weight(), 0.0);
  s.advance(0.1);
  EXPECT_NEAR(s.weight(), 1.0 / 3, 1e-12);
  s.advance(0.15);
  EXPECT_NEAR(s.weight(), 5.0 / 6, 1e-12);
  s.advance(0.05);
  EXPECT_FALSE(s.running());
  EXPECT_EQ(s.weight(), 1.0);
  s.advance(-1);  // idle: nothing happens
  EXPECT_EQ(s.weight(), 1.0);
}

TEST(LodFadeSchedule, ZeroOrInvalidTimeTurnsFadingOff) {
  for (double ms : {0.0, -5.0, std::nan("")}) {
    render::LodFadeSchedule s(ms);
    EXPECT_FALSE(s.enabled()) << ms;
    s.start();
    EXPECT_FALSE(s.running()) << ms;
    EXPECT_EQ(s.weight(), 1.0) << ms;
  }
}

TEST(LodFadeBlend, ChannelIsTheWeightedMeanRounded) {
  EXPECT_EQ(render::blend_channel(0, 255, 0.0), 0);
  EXPECT_EQ(render::blend_channel(0, 255, 1.0), 255);
  EXPECT_EQ(render::blend_channel(0, 255, 0.5), 128);  // 127.5 rounds up
  EXPECT_EQ(render::blend_channel(200, 100, 0.25), 175);
  EXPECT_EQ(render::blend_channel(10, 10, 0.7), 10);
}

class LodFadeRender : public RenderTest {
 protected:
  // The side view of a translucent sphere (opacity grows with the distance inside).
  const Vec3 eye_{-20.0, -150.0, 55.0};
  const Vec3 look_at_{-20.0, 0.0, 55.0};

  void SetUp() override {
    RenderTest::SetUp();
    scene_.subvolumes = {sphere(1, "d1", 35.0)};
    controller_ = std::make_unique<view::ViewController>(*link_, scene_);
    ASSERT_TRUE(renderer_->set_scene_layout({1}, {}).ok);
    ASSERT_TRUE(
        renderer_->set_user_shader(flat_shader("return 1.0 - exp(-distance / 25.0);"), "t.glsl")
            .ok);
  }

  // Coarse: the root alone; fine: every visible leaf.
  void set_fine(bool fine) {
    lod::LodOptions o = controller_->options().lod;
    o.split_solid_angle_sr = fine ? 0.0 : 1e9;
    o.max_nodes = 4096;
    controller_->set_lod_options(o);
  }

  render::CompleteFrame frame(render::LodCrossFade* fade, double seconds) {
    const auto inputs = render::frame_inputs(*controller_, camera(eye_, look_at_));
    return render::render_complete_frame(*controller_, *renderer_, *target_, inputs,
                                         {.fade = fade, .fade_seconds = seconds});
  }

  Scene scene_;
};

TEST_F(LodFadeRender, ACutChangeFadesOverFramesEachAtMostAboutHalfThePop) {
  // The pop: the coarse and the fine picture without fading.
  set_fine(false);
  const auto coarse = frame(nullptr, 0);
  set_fine(true);
  const auto fine = frame(nullptr, 0);
  ASSERT_GT(fine.cut_nodes, coarse.cut_nodes);
  const int pop = max_change(coarse.image, fine.image);
  ASSERT_GE(pop, 40) << "the cut change must be visible for this test to mean anything";

  renderer_->meshes().clear();
  set_fine(false);
  render::LodCrossFade fade(300);
  const auto f0 = frame(&fade, 0.1);  // the first picture: no fade
  EXPECT_EQ(f0.fade_weight, 1.0);
  EXPECT_EQ(max_change(f0.image, coarse.image), 0);

  set_fine(true);
  const auto f1 = frame(&fade, 0.1);  // the change: the fade starts at weight 0
  EXPECT_TRUE(fade.schedule().running());
  EXPECT_TRUE(renderer_->meshes().retained_differs());
  EXPECT_EQ(f1.fade_weight, 0.0);
  EXPECT_EQ(f1.cut_nodes, fine.cut_nodes);
  EXPECT_LE(max_change(f1.image, coarse.image), 1);

  const auto f2 = frame(&fade, 0.15);  // halfway
  EXPECT_NEAR(f2.fade_weight, 0.5, 1e-9);
  // The blend of the two pictures, within rounding.
  int off = 0;
  for (std::size_t i = 0; i < f2.image.pixels.size(); ++i) {
    const int expected = render::blend_channel(coarse.image.pixels[i], fine.image.pixels[i], 0.5);
    off = std::max(off, std::abs(int(f2.image.pixels[i]) - expected));
  }
  EXPECT_LE(off, 1);

  const auto f3 = frame(&fade, 0.15);  // the fade is over
  EXPECT_FALSE(fade.schedule().running());
  EXPECT_FALSE(renderer_->meshes().retained_differs());
  EXPECT_EQ(f3.fade_weight, 1.0);
  EXPECT_EQ(max_change(f3.image, fine.image), 0);

  // No frame of the fade changes by more than about half of the pop.
  const int limit = pop / 2 + 2;
  EXPECT_LE(max_change(f0.image, f1.image), limit);
  EXPECT_LE(max_change(f1.image, f2.image), limit);
  EXPECT_LE(max_change(f2.image, f3.image), limit);
}

TEST_F(LodFadeRender, FadingOffDrawsExactlyWhatAPlainRenderDraws) {
  set_fine(false);
  const auto coarse = frame(nullptr, 0);
  set_fine(true);
  const auto fine = frame(nullptr, 0);

  renderer_->meshes().clear();
  set_fine(false);
  render::LodCrossFade off(0);
  EXPECT_EQ(max_change(frame(&off, 0.1).image, coarse.image), 0);
  set_fine(true);
  const auto changed = frame(&off, 0.1);
  EXPECT_FALSE(off.schedule().running());
  EXPECT_FALSE(renderer_->meshes().retaining());
  EXPECT_EQ(changed.fade_weight, 1.0);
  EXPECT_EQ(max_change(changed.image, fine.image), 0);
}

TEST_F(LodFadeRender, TheRetainedSetIsTheOneShownBeforeTheChange) {
  set_fine(false);
  render::LodCrossFade fade(300);
  frame(&fade, 0.1);
  std::vector<NodeId> before;
  for (const auto& [node, mesh] : renderer_->meshes().meshes()) before.push_back(node);
  set_fine(true);
  frame(&fade, 0.1);
  std::vector<NodeId> after;
  for (const auto& [node, mesh] : renderer_->meshes().meshes()) after.push_back(node);
  ASSERT_NE(std::set(before.begin(), before.end()), std::set(after.begin(), after.end()));

  auto& meshes = renderer_->meshes();
  const auto triangles = meshes.triangles();
  meshes.exchange_retained();
  std::vector<NodeId> retained;
  for (const auto& [node, mesh] : meshes.meshes()) retained.push_back(node);
  EXPECT_EQ(std::set(retained.begin(), retained.end()), std::set(before.begin(), before.end()));
  meshes.exchange_retained();
  std::vector<NodeId> back;
  for (const auto& [node, mesh] : meshes.meshes()) back.push_back(node);
  EXPECT_EQ(std::set(back.begin(), back.end()), std::set(after.begin(), after.end()));
  EXPECT_EQ(meshes.triangles(), triangles);
}

}  // namespace
}  // namespace strielad::testing
