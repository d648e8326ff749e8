// SPDX-License-Identifier: Apache-2.0
// What the viewer's panel edits (PanelState) and what it shows (PanelInfo). The panel
// (panel/panel.h) changes the state and raises a flag for each change; the window loop
// of strielad-view applies what changed and clears the flag.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lod/camera_path.h"
#include "scene/scene.h"

namespace strielad::panel {

struct PanelState {
  Scene scene;                 // edited copy of the scene
  bool scene_changed = false;  // set by the panel when an edit is complete and valid
  std::string scene_error;     // why the last edit was not applied (empty: none)
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
  // Cross-fade between levels of detail, ms (0: off; render/lod_fade.h); read each frame.
  float lod_fade_ms = 300.0f;
  float exaggeration = 10.0f;
  bool exaggeration_changed = false;
  bool boxes = false;
  bool home = false;
  // Terrain (--terrain) and its drape image: drawn or not; the switches are offered
  // only where the session has them.
  bool terrain_available = false;
  bool terrain_shown = true;
  bool drape_available = false;
  bool drape_shown = true;
  // Flight tracks (--tracks): drawn or not, and the minutes of each track drawn before
  // the time shown.
  bool tracks_available = false;
  bool tracks_shown = true;
  float track_minutes = 2.0f;
  bool tracks_changed = false;
  // Scene files: the path the panel saves to and loads from (NAME.json, the camera as
  // a one-keyframe camera path in NAME.camera.json), and what the last save or load did.
  std::string scene_path = "scene.json";
  std::string file_status;
  std::string file_error;
  // The camera in the store's axis coordinates, kept current by the window loop (saved
  // with the scene); a loaded camera for the window loop to move to.
  std::optional<lod::Keyframe> camera;
  std::optional<lod::Keyframe> camera_loaded;
  // Shader editor.
  std::string shader_name;
  std::string shader_text;
  bool shader_compile = false;  // the editor's text should be compiled
  bool shader_reload = false;   // the file should be read again
  // A built-in look to load into the editor and compile (docs/view.md "Looks"); the
  // window loop fills in its source.
  enum class BuiltinLook { kNone, kClouds, kScalarOnSurface };
  BuiltinLook builtin_look = BuiltinLook::kNone;
  std::string shader_error;     // the last compile error (empty: none)
  int shader_error_line = 0;
};

// The renderer's counters of the last frame that the panel shows.
struct FrameCounters {
  double fragments_per_covered_pixel = 0;
  std::uint32_t max_fragments_per_pixel = 0;
  std::uint64_t fragment_capacity = 0;
  std::uint64_t dropped_fragments = 0;
  std::uint64_t truncated_pixels = 0;
  double geometry_ms = 0, resolve_ms = 0;
};

// The colour map of the "scalar on surface" look, for the legend: the title, the range
// and the map's colours at evenly spaced values from lo to hi (both ends included).
struct ScalarLegend {
  std::string title;
  double lo = 0, hi = 1;
  std::vector<std::array<float, 3>> colours;
};

struct PanelInfo {
  std::string dataset;
  std::optional<ScalarLegend> scalar_legend;  // the scalar look's colour bar, if shown
  double fps = 0, frame_ms = 0, cut_update_ms = 0;
  std::size_t cut_nodes = 0, pending = 0, stale_shown = 0;
  std::uint64_t results = 0, failed = 0, bytes_received = 0;
  std::size_t gpu_triangles = 0, gpu_bytes = 0;
  FrameCounters frame;
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
  bool on_earth = false;  // the store has a place on the Earth (geographic boxes)
};

}  // namespace strielad::panel
