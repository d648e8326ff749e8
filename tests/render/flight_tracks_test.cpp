// SPDX-License-Identifier: Apache-2.0
// Flight tracks in the picture (render/track_drawing.h): a track in front of an opaque
// sphere shows over it, one behind it is hidden by it, and the aircraft is a point.
#include "render_fixture.h"

namespace strielad::testing {
namespace {

const Vec3 kSouthEye{5.0, -320.0, 55.0};
const Vec3 kSouthTarget{5.0, 0.0, 55.0};

// A straight east-west segment at world y (km), 5.5 km up (55 km drawn), from x0 to x1.
std::shared_ptr<view::TrackLines> line_at(double y, double x0, double x1) {
  auto lines = std::make_shared<view::TrackLines>();
  lines->segments = {float(x0), float(y), 5.5f, float(x1), float(y), 5.5f};
  lines->heads = {float(x1), float(y), 5.5f};
  lines->tracks_shown = 1;
  return lines;
}

bool is_track(const std::array<std::uint8_t, 4>& p) { return p[1] > 80 && p[2] < 60 && p[0] > 150; }

// Track-coloured pixels in the three rows about the centre, between columns lo and hi.
int track_pixels(const render::RgbaImage& image, int lo, int hi) {
  const int kSize = image.height;
  int n = 0;
  for (int y = kSize / 2 - 2; y <= kSize / 2 + 1; ++y)
    for (int x = lo; x <= hi; ++x) n += is_track(image.at(x, y)) ? 1 : 0;
  return n;
}

TEST_F(RenderTest, TracksInFrontShowAndTracksBehindAreHidden) {
  Scene scene;
  scene.subvolumes = {sphere(1, "d1", 20.0)};
  const auto shader = flat_shader("return 1.0;");
  controller_ = std::make_unique<view::ViewController>(*link_, scene);
  const auto cam = camera(kSouthEye, kSouthTarget);
  const int centre = project(cam, kSphereCenter1).first;
  auto render_with = [&](std::shared_ptr<view::TrackLines> lines) {
    EXPECT_TRUE(renderer_->set_scene_layout({1}, {}).ok);
    EXPECT_TRUE(renderer_->set_user_shader(shader, "test.glsl").ok);
    auto inputs = render::frame_inputs(*controller_, cam);
    inputs.tracks = std::move(lines);
    return render::render_complete_frame(*controller_, *renderer_, *target_, inputs);
  };
  const auto front = render_with(line_at(-40.0, -80.0, 60.0));
  const auto behind = render_with(line_at(40.0, -80.0, 60.0));
  const auto none = render_with(nullptr);
  // Over the sphere's disc (a few pixels either side of its centre).
  EXPECT_GT(track_pixels(front.image, centre - 4, centre + 4), 6);
  EXPECT_EQ(track_pixels(behind.image, centre - 4, centre + 4), 0);
  // No track, no track colour; left of the sphere the track behind it shows.
  EXPECT_EQ(track_pixels(none.image, 0, kSize - 1), 0);
  const int left_edge = project(cam, {-75.0, 40.0, 55.0}).first;
  EXPECT_GT(track_pixels(behind.image, left_edge, left_edge + 6), 2);
}

}  // namespace
}  // namespace strielad::testing
