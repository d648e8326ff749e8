// SPDX-License-Identifier: Apache-2.0
// The view-fade measure (declared in lod_fade_bench.h).
#include "bench/lod_fade_bench.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <set>

#include "bench/sample_input.h"
#include "core/error.h"
#include "lod/camera_path.h"
#include "render/complete_frame.h"
#include "render/headless_context.h"
#include "render/lod_fade.h"
#include "render/offscreen_target.h"
#include "view/default_scene.h"
#include "view/local_server.h"
#include "view/view_controller.h"
#include "view/view_link.h"

namespace strielad::bench {
namespace {

void validate(const FadeBenchOptions& o) {
  if (!(o.fps > 0) || !std::isfinite(o.fps)) {
    throw make_error(ErrorCode::kInvalidArgument, "--fps {}: must be > 0", o.fps);
  }
  if (!(o.fly_seconds > 0) || !(o.from_s >= 0) || !(o.to_s > o.from_s) ||
      o.to_s > o.fly_seconds + 1e-9) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "--from {} --to {}: need 0 <= from < to <= --fly-seconds {}", o.from_s,
                     o.to_s, o.fly_seconds);
  }
  if (!(o.fade_ms > 0)) {
    throw make_error(ErrorCode::kInvalidArgument, "--fade-ms {}: must be > 0", o.fade_ms);
  }
}

std::set<NodeId> cut_nodes(const view::ViewController& controller) {
  std::set<NodeId> nodes;
  for (const auto& n : controller.cut().nodes()) nodes.insert(n.node);
  return nodes;
}

FadeRun run_path(const FadeBenchOptions& o, const std::filesystem::path& store, double fade_ms) {
  auto connection = view::open_local_store(store, view::LocalServerOptions{.threads = o.threads});
  auto link = std::make_unique<view::ViewLink>(std::move(connection.client));
  const Scene scene = view::default_scene(link->manifest(), 0);
  auto controller = std::make_unique<view::ViewController>(*link, scene);
  render::VolumeRenderer renderer;
  std::vector<std::uint32_t> ids;
  for (const auto& s : scene.subvolumes) ids.push_back(s.id);
  if (const auto layout = renderer.set_scene_layout(ids, scene.attributes); !layout.ok) {
    throw make_error(ErrorCode::kInternal, "view-fade: {}", layout.error);
  }
  render::OffscreenTarget target(o.width, o.height);
  render::LodCrossFade fade(fade_ms);
  const lod::WorldFrame& frame = controller->frame();
  const lod::CameraPath path = lod::default_fly_in_path(frame, o.fly_seconds);
  const lod::WorldCameraPath world(path, frame, "default fly-in");
  const double aspect = double(o.width) / double(o.height);
  const auto count = static_cast<std::size_t>(std::floor((o.to_s - o.from_s) * o.fps + 1e-9)) + 1;

  FadeRun run;
  run.fade_ms = fade_ms;
  std::vector<std::uint8_t> previous;
  std::set<NodeId> previous_cut;
  double render_ms = 0;
  std::vector<double> maxima;
  for (std::size_t i = 0; i < count; ++i) {
    const double t = world.start_time() + o.from_s + double(i) / o.fps;
    const lod::Camera camera = lod::pose_camera(world.sample(t), aspect, frame.domain());
    const auto inputs = render::frame_inputs(*controller, camera);
    // What was on screen (the previous frame's meshes and weight) from this camera.
    std::vector<std::uint8_t> before;
    if (i > 0) {
      fade.render(renderer, inputs, target.framebuffer(), o.width, o.height);
      before = render::VolumeRenderer::read_pixels(target.framebuffer(), o.width, o.height);
    }
    const auto f = render::render_complete_frame(*controller, renderer, target, inputs,
                                                 {.fade = &fade, .fade_seconds = 1.0 / o.fps});
    render_ms += f.render_ms;
    run.faded_frames += f.fade_weight < 1 ? 1 : 0;
    auto cut = cut_nodes(*controller);
    if (i > 0) {
      const bool cut_changed = cut != previous_cut;
      run.cut_changes += cut_changed ? 1 : 0;
      const FrameChange lod = frame_change(before, f.image.pixels);
      if (lod.max > run.lod.max) run.lod_at = i;
      run.lod.max = std::max(run.lod.max, lod.max);
      run.lod.p999 = std::max(run.lod.p999, lod.p999);
      if (cut_changed) maxima.push_back(lod.max);
      run.lod_changes.push_back(lod);
      const FrameChange motion = frame_change(previous, f.image.pixels);
      run.motion.max = std::max(run.motion.max, motion.max);
      run.motion.p999 = std::max(run.motion.p999, motion.p999);
      run.motion_changes.push_back(motion);
    }
    previous = f.image.pixels;
    previous_cut = std::move(cut);
    ++run.frames;
  }
  if (!maxima.empty()) {
    std::sort(maxima.begin(), maxima.end());
    run.lod_median_max = maxima[maxima.size() / 2];
  }
  run.render_ms_mean = render_ms / double(run.frames);
  controller.reset();
  link.reset();
  return run;
}

}  // namespace

FrameChange frame_change(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  if (a.size() != b.size() || a.size() % 4 != 0) {
    throw make_error(ErrorCode::kInvalidArgument, "frame change: images of {} and {} bytes",
                     a.size(), b.size());
  }
  std::vector<std::size_t> histogram(256, 0);
  const std::size_t pixels = a.size() / 4;
  for (std::size_t p = 0; p < pixels; ++p) {
    int d = 0;
    for (std::size_t c = 0; c < 4; ++c) {
      d = std::max(d, std::abs(int(a[p * 4 + c]) - int(b[p * 4 + c])));
    }
    ++histogram[static_cast<std::size_t>(d)];
  }
  FrameChange change;
  // The 99.9th percentile: the smallest d with at least 99.9 % of the pixels at or below.
  const auto needed = static_cast<std::size_t>(std::ceil(0.999 * double(pixels)));
  std::size_t seen = 0;
  bool found = false;
  for (int d = 0; d < 256; ++d) {
    if (histogram[static_cast<std::size_t>(d)] == 0) continue;
    change.max = d;
    seen += histogram[static_cast<std::size_t>(d)];
    if (!found && seen >= needed) {
      change.p999 = d;
      found = true;
    }
  }
  return change;
}

FadeBenchReport run_fade_bench(const FadeBenchOptions& o) {
  validate(o);
  FadeBenchReport report;
  report.options = o;
  std::filesystem::create_directories(o.work);
  const SampleInput input = ensure_sample_input({o.dims, 1, o.variables, o.seed}, o.work / "input");
  const auto store = o.work / "store";
  convert_sample_store(input, o.variables, o.brick, 0, store);
  const auto context = render::HeadlessContext::create();
  report.gl = render::current_gl_description();
  spdlog::info("view-fade: the fly-in from {} s to {} s at {} fps, fading off", o.from_s, o.to_s,
               o.fps);
  report.off = run_path(o, store, 0);
  spdlog::info("view-fade: the same with a {} ms fade", o.fade_ms);
  report.on = run_path(o, store, o.fade_ms);
  return report;
}

std::string fade_report_text(const FadeBenchReport& r) {
  const auto& o = r.options;
  std::string text = fmt::format(
      "strielad-bench view-fade: {}\nstore {}x{}x{} (brick {}), default scene; default fly-in "
      "({} s) from {} s to {} s at {} fps, {}x{} pixels\n\n"
      "Per-pixel change (largest channel difference, 0-255): level of detail = a frame "
      "against the previous frame's meshes and fade weight from the same camera; frame to "
      "frame = camera motion included.\n\n"
      "| fade | frames | cut changes | blended frames | LOD change: largest max | largest "
      "p99.9 | median max (frames whose cut changed) | frame to frame: largest max | largest "
      "p99.9 | render ms per frame |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n",
      r.gl, o.dims.x, o.dims.y, o.dims.z, o.brick, o.fly_seconds, o.from_s, o.to_s, o.fps,
      o.width, o.height);
  for (const FadeRun* run : {&r.off, &r.on}) {
    text += fmt::format("| {} | {} | {} | {} | {} (frame {}) | {} | {:g} | {} | {} | {:.0f} |\n",
                        run->fade_ms > 0 ? fmt::format("{:g} ms", run->fade_ms) : "off",
                        run->frames, run->cut_changes, run->faded_frames, run->lod.max,
                        run->lod_at, run->lod.p999, run->lod_median_max, run->motion.max,
                        run->motion.p999, run->render_ms_mean);
  }
  return text;
}

nlohmann::json fade_report_json(const FadeBenchReport& r) {
  const auto run_json = [](const FadeRun& run) {
    nlohmann::json lod = nlohmann::json::array(), motion = nlohmann::json::array();
    for (const auto& c : run.lod_changes) lod.push_back({c.max, c.p999});
    for (const auto& c : run.motion_changes) motion.push_back({c.max, c.p999});
    return nlohmann::json{{"fade_ms", run.fade_ms},
                          {"frames", run.frames},
                          {"cut_changes", run.cut_changes},
                          {"blended_frames", run.faded_frames},
                          {"lod_largest_max", run.lod.max},
                          {"lod_largest_max_frame", run.lod_at},
                          {"lod_largest_p999", run.lod.p999},
                          {"lod_median_max_cut_changed", run.lod_median_max},
                          {"motion_largest_max", run.motion.max},
                          {"motion_largest_p999", run.motion.p999},
                          {"render_ms_mean", run.render_ms_mean},
                          {"lod_per_frame_max_p999", lod},
                          {"motion_per_frame_max_p999", motion}};
  };
  const auto& o = r.options;
  return {{"suite", "view-fade"},
          {"gl", r.gl},
          {"command_line", o.command_line},
          {"dims", {o.dims.x, o.dims.y, o.dims.z}},
          {"brick", o.brick},
          {"size", {o.width, o.height}},
          {"fly_seconds", o.fly_seconds},
          {"from_s", o.from_s},
          {"to_s", o.to_s},
          {"fps", o.fps},
          {"off", run_json(r.off)},
          {"on", run_json(r.on)}};
}

}  // namespace strielad::bench
