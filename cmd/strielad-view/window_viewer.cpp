// SPDX-License-Identifier: Apache-2.0
#include "window_viewer.h"

#include <epoxy/gl.h>
// epoxy before GLFW: GLFW must not include a GL header of its own.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "panel/panel.h"
#include "render/complete_frame.h"
#include "render/slice_drawing.h"
#include "render/surface_scalar_look.h"
#include "render/volume_shaders.h"
#include "render/png_file.h"
#include "view/default_scene.h"
#include "view/sun_direction.h"

namespace strielad::view_cmd {
namespace {

// Mesh bytes uploaded to the GPU per frame at most (a burst of results spreads over
// frames instead of stalling one).
constexpr std::size_t kUploadBytesPerFrame = 48u << 20;

// Compiles the user's shader; the panel shows the error of one that does not compile.
void apply_shader(render::VolumeRenderer& renderer, panel::PanelState& state,
                  const std::string& text, const std::string& name) {
  const auto update = renderer.set_user_shader(text, name);
  if (update.ok) {
    state.shader_error.clear();
    state.shader_error_line = 0;
    spdlog::info("{}: shader compiled", name);
  } else {
    state.shader_error = update.error;
    state.shader_error_line = update.error_line;
    spdlog::warn("{} (the last good shader keeps running)", update.error);
  }
}

// The shader editor's starting point: the session's shader, compiled, or the built-in one.
panel::PanelState panel_with_session_shader(render::VolumeRenderer& renderer,
                                            const ViewerSession& session) {
  panel::PanelState state;
  state.shader_name = session.shader_name;
  state.shader_text = session.shader_source.empty() ? renderer.user_shader_source()
                                                    : session.shader_source;
  if (!session.shader_source.empty()) {
    apply_shader(renderer, state, session.shader_source, session.shader_name);
  }
  return state;
}

// The renderer's counters the panel shows.
panel::FrameCounters frame_counters(const render::FrameStats& f) {
  return {.fragments_per_covered_pixel = f.fragments_per_covered_pixel(),
          .max_fragments_per_pixel = f.max_fragments_per_pixel,
          .fragment_capacity = f.fragment_capacity,
          .dropped_fragments = f.dropped_fragments,
          .truncated_pixels = f.truncated_pixels,
          .geometry_ms = f.geometry_ms,
          .resolve_ms = f.resolve_ms};
}

view::ViewOptions view_options(const ViewerArgs& args, const ViewerSession& session) {
  view::ViewOptions options;
  options.vertical_exaggeration = session.exaggeration;
  options.lod.split_solid_angle_sr = args.lod_threshold_sr;
  options.lod.max_nodes = args.max_nodes;
  return options;
}

}  // namespace

WindowViewer::WindowViewer(GLFWwindow* window, const ViewerArgs& args, ViewerSession& session,
                           render::VolumeRenderer& renderer)
    : window_(window),
      args_(args),
      session_(session),
      renderer_(renderer),
      state_(panel_with_session_shader(renderer, session)),
      watch_(args.shader_file.empty() ? std::nullopt
                                      : std::optional<ShaderFileWatch>(args.shader_file)),
      controller_(*session.link, session.scene, view_options(args, session)),
      fade_(args.lod_fade_ms),
      camera_(view::home_orbit_camera(controller_.frame(), session.link->manifest(),
                                      session.scene.time)) {
  apply_scene_layout(session.scene);
  state_.scene = session.scene;
  state_.time_step = static_cast<int>(session.scene.time);
  state_.exaggeration = static_cast<float>(session.exaggeration);
  state_.lod_threshold_sr = static_cast<float>(args.lod_threshold_sr);
  state_.max_nodes = static_cast<int>(args.max_nodes);
  state_.lod_fade_ms = static_cast<float>(args.lod_fade_ms);
  state_.boxes = args.boxes;
  state_.terrain_available = session.terrain != nullptr;
  state_.drape_available = session.terrain && !args.terrain_image.empty();
  state_.tracks_available = session.tracks != nullptr;
  state_.track_minutes = static_cast<float>(args.track_minutes);
  info_.on_earth = controller_.frame().on_earth();
  if (session.advection) {
    playback_.emplace(*session.advection);
    playback_->set_step(controller_.time_step());
    state_.advect_available = true;
    state_.advect = args.advect;
  }
  info_.advect_status = session.advection_status;
  info_.vertical_placement = "heights: " + session.vertical_placement;
  info_.dataset = session.dataset_name;
  last_frame_ = last_stats_ = last_step_ = clock_type::now();
}

void WindowViewer::frame() {
  glfwPollEvents();
  const auto now = clock_type::now();
  const double dt = std::chrono::duration<double>(now - last_frame_).count();
  last_frame_ = now;
  // Frame time smoothed over about ten frames.
  frame_s_smoothed_ = frame_s_smoothed_ == 0 ? dt : 0.9 * frame_s_smoothed_ + 0.1 * dt;

  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  const ImGuiIO& io = ImGui::GetIO();
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  apply_mouse(window_, io, height, mouse_, camera_);
  apply_keys(window_, io, dt, int(session_.link->manifest().time.values.size()), camera_, state_);
  advance_playback(dt, now);
  apply_panel_edits(now);
  apply_shader_edits();

  // The cut, the results that arrived, the uploads, the frame.
  const double aspect = height > 0 ? double(width) / double(height) : 1.0;
  const lod::Camera cam = camera_.camera(aspect);
  const auto counters = controller_.update(cam);
  fade_.set_fade_ms(state_.lod_fade_ms, renderer_.meshes());
  fade_.sync(renderer_.meshes(), controller_.meshes(), kUploadBytesPerFrame, dt);
  const render::FrameInputs inputs = frame_inputs(cam, height);
  const render::FrameStats stats = fade_.render(renderer_, inputs, 0, width, height);
  info_.frame = frame_counters(stats);
  info_.nodes_moved = stats.nodes_moved;
  state_.camera = camera_keyframe();
  update_statistics(now, counters.cut_update_ms);
  present(width, height);
}

void WindowViewer::apply_scene_layout(const Scene& scene) {
  std::vector<std::uint32_t> ids;
  for (const auto& s : scene.subvolumes) ids.push_back(s.id);
  const auto update = renderer_.set_scene_layout(ids, scene.attributes);
  if (!update.ok) state_.shader_error = update.error;
}

// Playback: the next step once the current one is complete, at most play_fps; with
// advection, once the meshes have moved to the step's end (view/advection_playback.h).
void WindowViewer::advance_playback(double dt, clock_type::time_point now) {
  auto tick = view::AdvectionPlayback::Tick::kNoMap;
  if (advecting()) {
    playback_->set_seconds(state_.advect_seconds);
    tick = playback_->tick(dt, state_.playing, state_.play_fps, controller_.complete());
    state_.advect_seconds = static_cast<float>(playback_->seconds());
  }
  const bool plain_step_due =
      tick == view::AdvectionPlayback::Tick::kNoMap && controller_.complete() &&
      std::chrono::duration<double>(now - last_step_).count() >= 1.0 / state_.play_fps;
  if (state_.playing && (tick == view::AdvectionPlayback::Tick::kNextStep || plain_step_due)) {
    state_.time_step =
        (state_.time_step + 1) % int(session_.link->manifest().time.values.size());
    state_.time_changed = true;
  }
}

// What the panel and keys changed (errors are shown, nothing stops).
void WindowViewer::apply_panel_edits(clock_type::time_point now) {
  try {
    if (state_.time_changed) {
      state_.time_changed = false;
      controller_.set_time(static_cast<std::uint32_t>(state_.time_step));
      state_.scene.time = controller_.time_step();
      last_step_ = now;
      if (playback_) playback_->set_step(controller_.time_step());
      state_.advect_seconds = 0;
    }
    if (state_.scene_changed) {
      state_.scene_changed = false;
      state_.scene.time = controller_.time_step();
      controller_.set_scene(state_.scene);
      apply_scene_layout(state_.scene);
      info_.error.clear();
    }
    if (state_.lod_changed) {
      state_.lod_changed = false;
      auto lod = controller_.options().lod;
      lod.split_solid_angle_sr = state_.lod_threshold_sr;
      lod.max_nodes = static_cast<std::size_t>(std::max(state_.max_nodes, 1));
      controller_.set_lod_options(lod);
    }
    if (state_.exaggeration_changed) {
      state_.exaggeration_changed = false;
      const double ratio = state_.exaggeration / controller_.options().vertical_exaggeration;
      controller_.set_vertical_exaggeration(state_.exaggeration);
      camera_.rescale_vertical(ratio, controller_.frame().domain());
      state_.tracks_changed = true;  // on the globe they are placed at the exaggeration
    }
  } catch (const Error& e) {
    info_.error = e.what();
  }
  if (state_.home) {
    state_.home = false;
    camera_.home();
  }
  if (state_.camera_loaded) {
    const auto& frame = controller_.frame();
    try {
      camera_.look_from(frame.to_world(state_.camera_loaded->eye),
                        frame.to_world(state_.camera_loaded->target));
    } catch (const Error& e) {
      state_.file_error = e.what();
    }
    state_.camera_loaded.reset();
  }
}

// The camera in the store's axis coordinates, as a camera path keyframe (saved with the
// scene); nothing where the frame cannot take it back to axes.
std::optional<lod::Keyframe> WindowViewer::camera_keyframe() const {
  const auto& frame = controller_.frame();
  try {
    lod::Keyframe key;
    key.eye = frame.to_axis(camera_.eye());
    key.target = frame.to_axis(camera_.target());
    for (double v : {key.eye[0], key.eye[1], key.eye[2], key.target[0], key.target[1],
                     key.target[2]}) {
      if (!std::isfinite(v)) return std::nullopt;
    }
    if (key.eye == key.target) return std::nullopt;
    return key;
  } catch (const Error&) {
    return std::nullopt;
  }
}

void WindowViewer::compile_shader(const std::string& text) {
  apply_shader(renderer_, state_, text, state_.shader_name);
}

// The shader file when it changed on disk or the panel asks to reload it, and the
// editor's text when the panel asks to compile it.
void WindowViewer::apply_shader_edits() {
  if (watch_) {
    if (auto text = watch_->poll()) {
      state_.shader_text = *text;
      compile_shader(*text);
    }
  }
  if (state_.shader_reload && watch_) {
    state_.shader_reload = false;
    try {
      state_.shader_text = read_text_file(args_.shader_file);
      compile_shader(state_.shader_text);
    } catch (const Error& e) {
      state_.shader_error = e.what();
    }
  }
  if (state_.builtin_look != panel::PanelState::BuiltinLook::kNone) {
    state_.shader_text = state_.builtin_look == panel::PanelState::BuiltinLook::kClouds
                             ? render::default_user_shader()
                             : render::surface_scalar_source();
    state_.builtin_look = panel::PanelState::BuiltinLook::kNone;
    state_.shader_compile = true;
  }
  if (state_.shader_compile) {
    state_.shader_compile = false;
    compile_shader(state_.shader_text);
  }
}

void WindowViewer::show_colour_bar(const render::ColourBarLegend& legend) {
  panel::ScalarLegend shown{legend.title, legend.lo, legend.hi, {}};
  constexpr int kColours = 33;
  for (int k = 0; k < kColours; ++k) {
    shown.colours.push_back(render::colormap_color(legend.colormap, double(k) / (kColours - 1)));
  }
  info_.scalar_legend = std::move(shown);
}

render::FrameInputs WindowViewer::frame_inputs(const lod::Camera& cam, int height) {
  const auto& manifest = session_.link->manifest();
  render::FrameInputs inputs = render::frame_inputs(controller_, cam);
  inputs.time_seconds = view::seconds_since_first_step(manifest, controller_.time_step());
  if (advecting()) {
    inputs.motions = playback_->motions();
    inputs.time_seconds += playback_->seconds();
  }
  const double seconds_after = advecting() ? playback_->seconds() : 0.0;
  if (session_.tracks && state_.tracks_shown) {
    if (controller_.time_step() != tracks_step_ || seconds_after != tracks_seconds_ ||
        state_.tracks_changed) {
      state_.tracks_changed = false;
      ViewerArgs args = args_;
      args.track_minutes = state_.track_minutes;
      tracks_ = tracks_at(session_, args, controller_, seconds_after);
      tracks_step_ = controller_.time_step();
      tracks_seconds_ = seconds_after;
    }
    inputs.tracks = tracks_;
  }
  add_sun(inputs, seconds_after);
  if (session_.terrain && state_.terrain_shown) {
    add_terrain(inputs, cam, height);
    inputs.terrain_drape = state_.drape_shown;
  }
  info_.step_seconds = playback_ ? playback_->step_seconds() : 0;
  if (state_.boxes) add_cut_outlines(inputs);
  return inputs;
}

// The fixed sun of --sun fixed, or the true sun at the time shown (and where the panel
// says it is seen from).
void WindowViewer::add_sun(render::FrameInputs& inputs, double seconds_after) {
  if (args_.sun_fixed_direction) inputs.sun_direction = *args_.sun_fixed_direction;
  if (args_.sun != "time") return;
  if (const auto sun = view::sun_at_step(controller_.link().placer().frame(),
                                         session_.link->manifest(), controller_.time_step(),
                                         seconds_after)) {
    inputs.sun_direction = sun->direction;
    info_.sun_elevation_deg = sun->position.elevation_deg;
    info_.sun_viewpoint = sun->viewpoint == view::SunViewpoint::kDomainCentre
                              ? "over the domain centre"
                              : fmt::format("over the domain's sunniest point ({:.1f}, {:.1f})",
                                            sun->latitude_deg, sun->longitude_deg);
  }
}

// The terrain tiles selected for this camera (those loaded so far) and the panel's
// terrain line.
void WindowViewer::add_terrain(render::FrameInputs& inputs, const lod::Camera& cam, int height) {
  inputs.terrain =
      session_.terrain->update(cam, controller_.options().vertical_exaggeration, height);
  const auto t = session_.terrain->status();
  info_.terrain = fmt::format("terrain: {} tiles, {} triangles; {} loaded ({:.1f} ms each), {} "
                              "pending, cache {:.0f} MiB{}",
                              t.selected, t.triangles, t.loads,
                              t.loads ? t.load_ms / double(t.loads) : 0.0, t.pending,
                              double(t.cache_bytes) / 1048576.0,
                              t.error.empty() ? "" : "; " + t.error);
}

// --boxes: the cut's node boxes, yellow where the node's mesh is current, red where it is
// missing or stale.
void WindowViewer::add_cut_outlines(render::FrameInputs& inputs) const {
  for (const auto& n : controller_.cut().nodes()) {
    inputs.outline_boxes.push_back(controller_.cut().box(n.node));
    const bool current = controller_.meshes().entries().contains(n.node) &&
                         controller_.meshes().entries().at(n.node).current;
    inputs.outline_colors.push_back(current ? std::array<float, 4>{0.95f, 0.85f, 0.3f, 0.5f}
                                            : std::array<float, 4>{0.9f, 0.3f, 0.3f, 0.6f});
  }
}

// The panel's statistics; the server's are asked for once a second.
void WindowViewer::update_statistics(clock_type::time_point now, double cut_update_ms) {
  if (std::chrono::duration<double>(now - last_stats_).count() > 1.0) {
    last_stats_ = now;
    controller_.link().request_stats();
  }
  const auto link = controller_.link().counters();
  info_.fps = frame_s_smoothed_ > 0 ? 1.0 / frame_s_smoothed_ : 0;
  info_.frame_ms = frame_s_smoothed_ * 1000;
  info_.cut_update_ms = cut_update_ms;
  info_.cut_nodes = controller_.meshes().size();
  info_.pending = controller_.meshes().pending();
  info_.stale_shown = controller_.meshes().stale_shown();
  info_.complete = controller_.complete();
  info_.results = link.results;
  info_.failed = link.failed;
  info_.bytes_received = link.bytes_received;
  info_.gpu_triangles = renderer_.meshes().triangles();
  info_.gpu_bytes = renderer_.meshes().bytes();
  if (controller_.last_error()) info_.error = *controller_.last_error();
  if (!controller_.server_stats_json().empty()) {
    try {
      const auto stats = nlohmann::json::parse(controller_.server_stats_json());
      info_.cache_hit_rate = stats.at("cache").at("hit_rate").get<double>();
    } catch (const std::exception&) {
      info_.cache_hit_rate = -1;
    }
  }
}

// The panel over the rendered view, the --screenshot of the last frame, the swap.
void WindowViewer::present(int width, int height) {
  panel::draw_panel(state_, info_, session_.link->manifest());
  ImGui::Render();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  ++frames_;
  const bool last = args_.frames > 0 && frames_ >= args_.frames;
  if (last && !args_.screenshot.empty()) {
    glFinish();
    render::write_png(args_.screenshot,
                      render::RgbaImage{width, height,
                                        render::VolumeRenderer::read_pixels(0, width, height)});
    spdlog::info("{}: screenshot of frame {}", args_.screenshot, frames_);
  }
  glfwSwapBuffers(window_);
  if (last) glfwSetWindowShouldClose(window_, GLFW_TRUE);
  if (controller_.connection_lost()) {
    glfwSetWindowTitle(window_, "strielad-view: connection to the server lost");
  }
}

}  // namespace strielad::view_cmd
