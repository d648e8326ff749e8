// SPDX-License-Identifier: Apache-2.0
#include <memory>

#include "cli/tool_main.h"
#include "core/error.h"
#include "viewer_args.h"
#include "viewer_session.h"

namespace strielad {
namespace {

// What to view: a local store or a server, the scene, the time step and the shader.
void add_source_options(CLI::App& app, view_cmd::ViewerArgs& args) {
  app.add_option("store", args.store, "A local store directory, served in-process");
  app.add_option("--connect", args.connect, "HOST:PORT of a running strielad-serve");
  app.add_option("--dataset", args.dataset,
                 "With --connect: the store's name under the server's --root");
  app.add_option("--token-file", args.token_file,
                 "With --connect: file holding the server's shared secret");
  app.add_option("--scene", args.scene_file,
                 "Scene JSON (formats/scene.md); default: cloud water, cloud ice and rain "
                 "where the store has clw, cli, qr");
  app.add_option("--time", args.time, "Time step to show first (overrides the scene's)");
  app.add_option("--shader", args.shader_file,
                 "GLSL file with color() and alpha() (docs/view.md \"User shaders\"); reloaded "
                 "when it changes. Default: examples/shaders/clouds.glsl, built in");
  app.add_option("--look", args.look,
                 "Built-in shader (docs/view.md \"Looks\"): 'clouds' (default: soft, "
                 "sun-lit, translucent where thin) or 'scalar' (opaque surfaces coloured by "
                 "--color-by, with a legend)")
      ->check(CLI::IsMember({"clouds", "scalar"}));
  app.add_option("--color-by", args.color_by,
                 "With --look scalar: the variable to colour by, or U,V[,W] for the "
                 "magnitude of a vector (ua,va: horizontal wind speed); added to the "
                 "scene's attributes when missing");
  app.add_option("--color-range", args.color_range,
                 "With --look scalar: LO,HI of the colour map (default: the variable's "
                 "data range in the store; 0 to the largest magnitude for a vector)");
  app.add_option("--colormap", args.colormap,
                 "With --look scalar: viridis (default), magma, coolwarm, greys, turbo");
}

// How the view is cut and drawn, and the in-process server's resources.
void add_view_options(CLI::App& app, view_cmd::ViewerArgs& args) {
  app.add_option("--exaggeration", args.exaggeration,
                 "Vertical exaggeration of the world frame (default: from the domain's "
                 "extents, 10 for the paper's grid, 200 for a global one; 10 under "
                 "--camera; docs/view.md \"Defaults for any domain\")")
      ->check(CLI::PositiveNumber);
  app.add_option("--shape", args.shape,
                 "World shape: 'auto' (default) the WGS84 globe for a domain wider than 30 "
                 "degrees of longitude or latitude (every global one), the tangent plane "
                 "otherwise; 'plane'; or 'globe' (docs/view.md \"The globe\")")
      ->check(CLI::IsMember({"auto", "plane", "globe"}));
  app.add_option("--lod-threshold", args.lod_threshold_sr,
                 "Split a node covering more than this solid angle, sr (default 0.01)");
  app.add_option("--max-nodes", args.max_nodes, "Most nodes in the cut (default 4096)");
  app.add_option("--lod-fade-ms", args.lod_fade_ms,
                 "Cross-fade when the level of detail changes, ms (default 300; 0: off; "
                 "camera paths advance 1/fps per frame)");
  app.add_option("--max-fragment-mib", args.max_fragment_mib,
                 "A-buffer fragment memory bound, MiB (default 256: 16 M fragments)");
  app.add_flag("--boxes", args.boxes, "Outline the cut's node boxes");
  app.add_option("--size", args.size, "WIDTHxHEIGHT of the window or image (1280x720)");
  app.add_option("--threads", args.threads,
                 "In-process server: extraction workers (default: one per core)");
  app.add_option("--cache-mib", args.cache_mib,
                 "In-process server: brick cache budget, MiB (default 1024)");
}

// Wind advection between time steps (docs/advection.md).
void add_advection_options(CLI::App& app, view_cmd::ViewerArgs& args) {
  app.add_flag("--advect", args.advect,
               "Move the meshes with the wind between time steps (smooth playback; "
               "docs/advection.md)");
  app.add_option("--wind", args.wind, "Wind components U,V,W (default ua,va,wa)");
  app.add_option("--wind-store", args.wind_store,
                 "Store to read the wind from (default: STORE; with --connect, the "
                 "served store's directory if this machine can read it)");
  app.add_option("--wind-level", args.wind_level,
                 "Octree level of the wind (default: the finest with at most 4 M "
                 "samples)");
  app.add_option("--advect-seconds", args.advect_seconds,
                 "Offscreen: draw the step's meshes moved this many seconds towards the "
                 "next step (implies --advect)");
  app.add_option("--integrator", args.integrator,
                 "Advection integrator: rk4 (default, 60 s steps), euler, dopri5 "
                 "(adaptive), rosenbrock (adaptive, for stiff flow)")
      ->check(CLI::IsMember({"euler", "rk4", "dopri5", "rosenbrock"}));
  app.add_option("--advect-step", args.advect_step_s,
                 "Advection step in seconds (fixed-step integrators; the adaptive ones' "
                 "first step), default 60")
      ->check(CLI::PositiveNumber);
  app.add_option("--advect-rtol", args.advect_rtol,
                 "Relative tolerance of the adaptive integrators (default 1e-6)")
      ->check(CLI::PositiveNumber);
}

// The sun, flight tracks and terrain.
void add_geography_options(CLI::App& app, view_cmd::ViewerArgs& args) {
  app.add_option("--sun", args.sun,
                 "Light: 'time' (default) the sun's true direction at the simulation "
                 "time over the domain centre (night is dark), or over the domain's "
                 "sunniest point for domains wider than 30 degrees of longitude; or "
                 "'fixed' (from the south-southeast, 54 degrees up, whatever the time)")
      ->check(CLI::IsMember({"time", "fixed"}));
  app.add_option("--tracks", args.tracks_file,
                 "Flight tracks: CSV with columns id,time,lon,lat,altitude, or a CF "
                 "trajectory NetCDF file (docs/terrain-and-tracks.md)");
  app.add_option("--track-minutes", args.track_minutes,
                 "Draw the part of each track flown in the last N minutes (default 2)")
      ->check(CLI::Range(0.0, 1e6));
  app.add_option("--terrain", args.terrain_file,
                 "Terrain: a DEM as CF-NetCDF (lon/lat or rotated-pole grid) or any raster "
                 "GDAL reads (GeoTIFF...), docs/terrain-and-tracks.md");
  app.add_option("--terrain-var", args.terrain_var,
                 "NetCDF DEM variable (default: standard_name surface_altitude, or HSURF, "
                 "z_ifc, topography_c, orog, elevation)");
  app.add_option("--terrain-image", args.terrain_image,
                 "Georeferenced image (any raster GDAL reads, RGB or grey) draped over the "
                 "terrain instead of height colours");
  app.add_option("--terrain-error", args.terrain_error,
                 "Terrain level of detail: split tiles whose error exceeds this many "
                 "pixels (default 2)")
      ->check(CLI::PositiveNumber);
  app.add_option("--terrain-cache-mib", args.terrain_cache_mib,
                 "Terrain tile cache bound, MiB (default 256)")
      ->check(CLI::PositiveNumber);
}

// Offscreen images, camera paths and the window's smoke-test exit.
void add_output_options(CLI::App& app, view_cmd::ViewerArgs& args) {
  app.add_flag("--offscreen", args.offscreen,
               "Render without a window (EGL; no X server needed) once the cut has fully "
               "arrived, write --out and exit");
  app.add_option("--camera", args.camera_file,
                 "Camera path JSON (formats/camera-path.md): one keyframe for one image, "
                 "several for numbered frames at --fps; default: the home view");
  app.add_option("--fps", args.fps, "Frames per second of a camera path (default 30)");
  app.add_option("--out", args.out,
                 "Image file (PNG); for a camera path a pattern with {} for the frame "
                 "number, e.g. frames/f{:04}.png");
  app.add_flag("--json", args.json, "Offscreen: one JSON line of statistics per frame");
  app.add_option("--frames", args.frames,
                 "Window: close after this many frames (for smoke tests; 0 = never)");
  app.add_option("--screenshot", args.screenshot,
                 "Window: save the last frame, panel included, as PNG on exit");
}

// The flags that cannot go together, as given on the command line; --advect-seconds
// implies --advect.
void check_command_line_flags(view_cmd::ViewerArgs& args) {
  if (args.store.empty() == args.connect.empty()) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "give exactly one of STORE or --connect HOST:PORT");
  }
  if (!args.connect.empty() && args.dataset.empty()) {
    throw make_error(ErrorCode::kInvalidArgument, "--connect needs --dataset NAME");
  }
  if (args.advect_seconds && !args.offscreen) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "--advect-seconds is for --offscreen; the window has a slider");
  }
  if (args.advect_seconds) args.advect = true;
  const bool terrain_flags = !args.terrain_var.empty() || !args.terrain_image.empty();
  if (terrain_flags && args.terrain_file.empty() && args.scene_file.empty()) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "--terrain-var and --terrain-image need --terrain FILE");
  }
}

// The flags that cannot go together once the scene file's settings are filled in.
void check_flags_with_scene_settings(const view_cmd::ViewerArgs& args) {
  if (args.terrain_file.empty() &&
      (!args.terrain_var.empty() || !args.terrain_image.empty())) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "--terrain-var and --terrain-image need --terrain FILE");
  }
  if (args.offscreen && args.out.empty()) {
    throw make_error(ErrorCode::kInvalidArgument, "--offscreen needs --out FILE.png");
  }
}

}  // namespace
}  // namespace strielad

int main(int argc, char** argv) {
  using namespace strielad;
  const cli::ToolSpec spec{
      "strielad-view",
      "Explore a STRIELAD store (STORE, served in-process) or a strielad-serve (--connect): "
      "level-of-detail cut, A-buffer pseudo-volumes, live GLSL colour functions",
      [](CLI::App& app, cli::Action& action) {
        auto args = std::make_shared<view_cmd::ViewerArgs>();
        add_source_options(app, *args);
        add_view_options(app, *args);
        add_advection_options(app, *args);
        add_geography_options(app, *args);
        add_output_options(app, *args);
        app.callback([args, &action, &app] {
          args->sun_given = app.count("--sun") > 0;
          action = [args] {
            check_command_line_flags(*args);
            *args = view_cmd::with_scene_settings(*args);
            check_flags_with_scene_settings(*args);
            return args->offscreen ? view_cmd::run_offscreen(*args) : view_cmd::run_window(*args);
          };
        });
      }};
  return cli::run_tool(spec, argc, argv);
}
