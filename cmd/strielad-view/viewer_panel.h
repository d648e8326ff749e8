// SPDX-License-Identifier: Apache-2.0
// The Dear ImGui panel of strielad-view: sub-volumes, time, level of detail, vertical
// exaggeration, the shader editor and live statistics. The panel edits a PanelState;
// the window loop applies what changed.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "format/manifest.h"
#include "render/volume_renderer.h"
#include "scene/scene.h"

namespace strielad::view_cmd {

struct PanelState {
  Scene scene;                 // edited copy of the scene
  bool scene_changed = false;  // set by the panel when an edit is complete
  int time_step = 0;
  bool time_changed = false;
  bool playing = false;
  float play_fps = 2.0f;       // time steps per second at most (each waits to be complete)
  // Wind advection: the meshes drawn advect_seconds after their step.
  bool advect = false;
  bool advect_available = false;
  float advect_seconds = 0;
  float lod_threshold_sr = 0.01f;
  int max_nodes = 4096;
  bool lod_changed = false;
  float exaggeration = 10.0f;
  bool exaggeration_changed = false;
  bool boxes = false;
  bool home = false;
  // Shader editor.
  std::string shader_name;
  std::string shader_text;
  bool shader_compile = false;  // the editor's text should be compiled
  bool shader_reload = false;   // the file should be read again
  std::string shader_error;     // the last compile error (empty: none)
  int shader_error_line = 0;
};

struct PanelInfo {
  std::string dataset;
  double fps = 0, frame_ms = 0, cut_update_ms = 0;
  std::size_t cut_nodes = 0, pending = 0, stale_shown = 0;
  std::uint64_t results = 0, failed = 0, bytes_received = 0;
  std::size_t gpu_triangles = 0, gpu_bytes = 0;
  render::FrameStats frame;
  double cache_hit_rate = -1;  // from the server's stats; < 0 unknown
  std::string error;           // the last error from the server, if any
  bool complete = false;
  std::string advect_status;   // wind source, or why advection is unavailable
  double step_seconds = 0;     // length of the current step (0: no map yet)
  std::size_t nodes_moved = 0;
  std::optional<double> sun_elevation_deg;  // the true sun's, when the store has a date
  std::string sun_viewpoint;                // where it is seen from (view/sun_direction.h)
  std::string terrain;  // terrain status line (empty: no --terrain)
  std::string vertical_placement;  // how heights are placed (view/height_placement.h)
};

void draw_panel(PanelState& state, const PanelInfo& info, const format::Manifest& manifest);

}  // namespace strielad::view_cmd
