// SPDX-License-Identifier: Apache-2.0
// The interactive window's frames: what the viewer keeps from one frame to the next
// (panel state, level-of-detail controller, camera, playback clock) and the steps of one
// frame: input, playback, the panel's edits, the shader's edits, the render and the
// panel. The window, the session and the renderer are run_window's; the frame loop
// never waits on the network.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "lod/camera_path.h"
#include "render/colour_bar_legend.h"
#include "render/volume_renderer.h"
#include "shader_file_watch.h"
#include "view/advection_playback.h"
#include "view/globe_view.h"
#include "view/orbit_camera.h"
#include "view/view_controller.h"
#include "viewer_args.h"
#include "panel/panel_state.h"
#include "viewer_session.h"
#include "window_input.h"

struct GLFWwindow;

namespace strielad::view_cmd {

class WindowViewer {
 public:
  using clock_type = std::chrono::steady_clock;

  // The panel starts from the session and `args`; the session's shader is compiled
  // (an error is shown in the panel, the built-in shader keeps running).
  WindowViewer(GLFWwindow* window, const ViewerArgs& args, ViewerSession& session,
               render::VolumeRenderer& renderer);
  // The scalar look's colour map, shown in the panel's legend section.
  void show_colour_bar(const render::ColourBarLegend& legend);

  // One frame, from the events to the swap; asks the window to close after --frames.
  void frame();

 private:
  bool advecting() const { return playback_ && state_.advect; }
  void apply_scene_layout(const Scene& scene);
  void compile_shader(const std::string& text);
  void advance_playback(double dt, clock_type::time_point now);
  void apply_panel_edits(clock_type::time_point now);
  void apply_shader_edits();
  std::optional<lod::Keyframe> camera_keyframe() const;
  render::FrameInputs frame_inputs(const lod::Camera& cam, int height);
  void add_sun(render::FrameInputs& inputs, double seconds_after);
  void add_terrain(render::FrameInputs& inputs, const lod::Camera& cam, int height);
  void add_cut_outlines(render::FrameInputs& inputs) const;
  void update_statistics(clock_type::time_point now, double cut_update_ms);
  void present(int width, int height);

  GLFWwindow* window_;
  const ViewerArgs& args_;
  ViewerSession& session_;
  render::VolumeRenderer& renderer_;
  panel::PanelState state_;
  std::optional<ShaderFileWatch> watch_;
  view::ViewController controller_;
  render::LodCrossFade fade_;
  view::OrbitCamera camera_;
  std::optional<view::AdvectionPlayback> playback_;
  // The tracks windowed at tracks_step_ plus tracks_seconds_ (windowed again only when
  // the time moved).
  std::shared_ptr<const view::TrackLines> tracks_;
  std::uint32_t tracks_step_ = ~0u;
  double tracks_seconds_ = -1;
  Mouse mouse_;
  panel::PanelInfo info_;
  clock_type::time_point last_frame_;
  clock_type::time_point last_stats_;
  clock_type::time_point last_step_;
  double frame_s_smoothed_ = 0;
  std::size_t frames_ = 0;
};

}  // namespace strielad::view_cmd
