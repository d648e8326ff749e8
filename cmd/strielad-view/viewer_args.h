// SPDX-License-Identifier: Apache-2.0
// The flags of strielad-view (docs/view.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "lod/lod_cut.h"
#include "lod/world_frame.h"
#include "render/lod_fade.h"
#include "render/volume_renderer.h"

namespace strielad::view_cmd {

struct ViewerArgs {
  std::string store;        // a local store: served in-process
  std::string connect;      // HOST:PORT of a strielad-serve
  std::string dataset;      // with --connect: the store's name under the server's root
  std::string token_file;   // with --connect
  std::string scene_file;   // formats/scene.md; default: view::default_scene
  std::optional<std::uint32_t> time;
  std::string shader_file;  // the user's color()/alpha(); default: the built-in clouds
  // The built-in look (docs/view.md "Looks"): "clouds" (soft, sun-lit clouds) or
  // "scalar" (opaque surfaces coloured by --color-by through --colormap over
  // --color-range, with a legend).
  std::string look = "clouds";
  std::string color_by;     // VAR, or U,V[,W] for the magnitude of a vector
  std::string color_range;  // LO,HI; default: the variable's data range in the store
  std::string colormap = "viridis";
  // --exaggeration; unset: the domain's default (view/default_exaggeration.h), or
  // lod::kDefaultVerticalExaggeration under a camera path (formats/camera-path.md).
  std::optional<double> exaggeration;
  // --shape: "auto" (the globe for domains wider than lod::kGlobeMinExtentDeg), "plane"
  // or "globe" (lod::FrameShape).
  std::string shape = "auto";
  double lod_threshold_sr = lod::kDefaultSplitSolidAngleSr;
  std::size_t max_nodes = lod::kDefaultMaxNodes;
  double lod_fade_ms = render::kDefaultLodFadeMs;  // cross-fade of LOD changes; 0: off
  double max_fragment_mib = render::kDefaultMaxFragmentBytes / double(1 << 20);
  bool boxes = false;
  std::string size = "1280x720";
  unsigned threads = 0;
  double cache_mib = 1024;
  // Wind advection between steps (docs/advection.md).
  bool advect = false;            // start with meshes moving with the wind
  std::string wind = "ua,va,wa";  // the wind components U,V,W
  std::string wind_store;         // where to read the wind; default: STORE
  std::optional<std::uint32_t> wind_level;
  std::optional<double> advect_seconds;  // offscreen: seconds after the step
  std::string integrator = "rk4";        // lib/advect method
  double advect_step_s = 60;             // fixed step, or the adaptive methods' first
  double advect_rtol = 1e-6;             // adaptive methods
  std::string sun = "time";  // "time": the true sun at the simulation time; "fixed"
  // With "fixed": towards the sun in the world frame (x east, y north, z up); unset: the
  // built-in light. Set from the scene's "sun" {"elevation", "azimuth"}.
  std::optional<Vec3> sun_fixed_direction;
  bool sun_given = false;  // --sun was on the command line (it overrides the scene)
  bool sun_time_asked = false;  // the scene asks for {"mode": "time"} (not a default)
  std::string tracks_file;   // flight tracks CSV (scenery/flight_tracks.h)
  double track_minutes = 2;  // drawn: the last minutes of each track
  // Terrain (docs/terrain-and-tracks.md).
  std::string terrain_file;   // DEM: NetCDF or any raster GDAL reads
  std::string terrain_var;    // NetCDF variable (default: found by standard_name / name)
  std::string terrain_image;  // georeferenced drape image
  double terrain_error = 2.0; // screen-space error bound, pixels
  double terrain_cache_mib = 256;
  // Headless.
  bool offscreen = false;
  std::string camera_file;  // formats/camera-path.md: one keyframe, or a path
  double fps = 30;
  std::string out;          // frame.png, or a pattern with {} for the frame number
  bool json = false;
  // Window: stop after this many frames (0 = run until closed) and save the last one,
  // panel included (for smoke tests and README pictures).
  std::size_t frames = 0;
  std::string screenshot;
};

int run_window(const ViewerArgs& args);
int run_offscreen(const ViewerArgs& args);

}  // namespace strielad::view_cmd
