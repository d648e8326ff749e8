// SPDX-License-Identifier: Apache-2.0
// `strielad-view --offscreen`: images of complete views without a window (EGL), for
// batch figures, tests and the view benchmark.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli/image_size.h"
#include "core/error.h"
#include "lod/camera_path.h"
#include "look_choice.h"
#include "render/complete_frame.h"
#include "render/headless_context.h"
#include "view/default_scene.h"
#include "view/globe_view.h"
#include "view/orbit_camera.h"
#include "view/sun_direction.h"
#include "view/view_controller.h"
#include "viewer_args.h"
#include "viewer_session.h"

namespace strielad::view_cmd {
namespace {

std::filesystem::path frame_path(const std::string& pattern, std::size_t frame, bool many) {
  if (pattern.find('{') != std::string::npos) {
    try {
      return fmt::format(fmt::runtime(pattern), frame);
    } catch (const fmt::format_error& e) {
      throw make_error(ErrorCode::kInvalidArgument, "--out {}: not a valid pattern: {}", pattern,
                       e.what());
    }
  }
  if (!many) return pattern;
  // frames.png -> frames_0000.png
  std::filesystem::path p(pattern);
  return p.parent_path() / fmt::format("{}_{:04}{}", p.stem().string(), frame, p.extension().string());
}

// The cameras to render: a camera path's samples at --fps, one keyframe, or the home view.
std::vector<lod::Camera> offscreen_cameras(const ViewerArgs& args,
                                           const view::ViewController& controller, double aspect) {
  std::vector<lod::Camera> cameras;
  if (!args.camera_file.empty()) {
    const auto path = lod::load_camera_path_file(args.camera_file);
    const lod::WorldCameraPath world(path, controller.frame(), args.camera_file);
    if (!(args.fps > 0) || !std::isfinite(args.fps)) {
      throw make_error(ErrorCode::kInvalidArgument, "--fps {}: must be > 0", args.fps);
    }
    const double span = world.end_time() - world.start_time();
    const auto frames = static_cast<std::size_t>(std::floor(span * args.fps + 1e-9)) + 1;
    for (std::size_t i = 0; i < frames; ++i) {
      const auto pose = world.sample(world.start_time() + double(i) / args.fps);
      cameras.push_back(lod::pose_camera(pose, aspect, controller.frame().domain()));
    }
  } else {
    cameras.push_back(view::home_orbit_camera(controller.frame(), controller.link().manifest(),
                                              controller.scene().time)
                          .camera(aspect));
  }
  return cameras;
}

// With --advect-seconds: the step's displacement map, computed before the first frame,
// drawn `advect_s` seconds after the step. Without it, no motion.
std::vector<render::MeshMotion> advection_motions(const ViewerArgs& args,
                                                  const ViewerSession& session,
                                                  const view::ViewController& controller,
                                                  double advect_s) {
  std::vector<render::MeshMotion> motions;
  if (!args.advect_seconds) return motions;
  if (!std::isfinite(advect_s) || advect_s < 0) {
    throw make_error(ErrorCode::kInvalidArgument, "--advect-seconds {}: must be >= 0", advect_s);
  }
  session.advection->want({controller.time_step()});
  session.advection->wait_idle();
  auto map = session.advection->map(controller.time_step());
  if (!map) {
    throw make_error(ErrorCode::kInvalidArgument, "--advect-seconds: step {}: {}",
                     controller.time_step(),
                     session.advection->error().empty() ? "the store's last step has no next "
                                                          "step to advect towards"
                                                        : session.advection->error());
  }
  if (advect_s > map->seconds) {
    spdlog::warn("--advect-seconds {}: the step lasts {} s; drawn at its end", advect_s,
                 map->seconds);
  }
  motions.push_back({std::move(map), advect_s});
  return motions;
}

// The terrain tiles of the camera's final selection, all loaded (deterministic images);
// `wait_ms` is how long the loading took. \error kCancelled after 10 minutes.
std::shared_ptr<const view::TerrainFrame> fully_loaded_terrain(view::TerrainTiles& terrain,
                                                               const lod::Camera& camera,
                                                               double exaggeration, int height,
                                                               double& wait_ms) {
  std::shared_ptr<const view::TerrainFrame> frame;
  const auto t0 = std::chrono::steady_clock::now();
  while (true) {
    frame = terrain.update(camera, exaggeration, height);
    if (terrain.complete()) break;
    if (std::chrono::steady_clock::now() - t0 > std::chrono::minutes(10)) {
      throw make_error(ErrorCode::kCancelled, "the terrain was not loaded after 600 s");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  wait_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
  return frame;
}

// What is common to every frame of one run, for its --json report line.
struct RunFacts {
  const ViewerSession& session;
  const view::ViewController& controller;
  render::VolumeRenderer& renderer;
  double advect_s = 0;
  const std::optional<view::SunAtTime>& sun;
  const std::shared_ptr<const view::TrackLines>& tracks;
  double track_window_ms = 0;
  const std::vector<render::MeshMotion>& motions;
};

// The --json line of one frame.
nlohmann::json frame_json_line(const RunFacts& run, std::size_t i,
                               const std::filesystem::path& out,
                               const render::CompleteFrame& frame, double terrain_wait_ms) {
  const auto& session = run.session;
  const auto& sun = run.sun;
  const auto& tracks = run.tracks;
  const auto& motions = run.motions;
  const auto& s = frame.stats;
  const auto terrain_status = session.terrain ? session.terrain->status() : view::TerrainStatus{};
  nlohmann::json line{{"frame", i},
                      {"file", out.string()},
                      {"cut_nodes", frame.cut_nodes},
                      {"nodes_with_mesh", frame.nodes_with_mesh},
                      {"triangles", s.triangles_drawn},
                      {"advect_seconds", run.advect_s},
                      {"sun_elevation_deg", sun ? nlohmann::json(sun->position.elevation_deg) : nlohmann::json()},
                      {"sun_azimuth_deg", sun ? nlohmann::json(sun->position.azimuth_deg) : nlohmann::json()},
                      {"sun_seen_from", sun ? nlohmann::json({sun->latitude_deg, sun->longitude_deg}) : nlohmann::json()},
                      {"sun_viewpoint", !sun ? nlohmann::json() : sun->viewpoint == view::SunViewpoint::kDomainCentre ? "domain centre" : "sunniest point"},
                      {"vertical_exaggeration", session.exaggeration},
                      {"vertical_placement", session.vertical_placement},
                      {"nodes_moved", s.nodes_moved},
                      {"lod_fade_weight", frame.fade_weight},
                      {"tracks_shown", tracks ? tracks->tracks_shown : 0},
                      {"track_segments", tracks ? tracks->segment_count() : 0},
                      {"track_window_ms", run.track_window_ms},
                      {"advect_trajectories", motions.empty() ? 0 : motions[0].map->points()},
                      {"advect_evaluations", motions.empty() ? 0 : motions[0].map->evaluations},
                      {"advect_map_ms", motions.empty() ? 0.0 : motions[0].map->compute_seconds * 1e3},
                      {"terrain_tiles", s.terrain_tiles},
                      {"terrain_triangles", s.terrain_triangles},
                      {"terrain_load_ms", terrain_wait_ms},
                      {"terrain_tiles_loaded", terrain_status.loads},
                      {"terrain_tile_ms", terrain_status.loads ? terrain_status.load_ms / double(terrain_status.loads) : 0.0},
                      {"wait_ms", frame.wait_ms},
                      {"render_ms", frame.render_ms},
                      {"geometry_ms", s.geometry_ms},
                      {"resolve_ms", s.resolve_ms},
                      {"fragments", s.fragments},
                      {"dropped_fragments", s.dropped_fragments},
                      {"covered_pixels", s.covered_pixels},
                      {"truncated_pixels", s.truncated_pixels},
                      {"max_fragments_per_pixel", s.max_fragments_per_pixel},
                      {"failed_nodes", run.controller.failed_nodes()}};
  line["slice_triangles"] = run.renderer.meshes().slice_triangles();
  line["slices"] = nlohmann::json::array();
  for (std::size_t k = 0; k < frame.slice_styles.size(); ++k) {
    const auto& style = frame.slice_styles[k];
    line["slices"].push_back({{"id", run.controller.scene().slices[k].id},
                              {"colormap", style.colormap},
                              {"range", {style.lo, style.hi}}});
  }
  return line;
}

// The session's shader in the renderer; one that does not compile is an error here (no
// window to show it in).
void apply_session_shader(render::VolumeRenderer& renderer, const ViewerSession& session) {
  if (session.shader_source.empty()) return;
  const auto update = renderer.set_user_shader(session.shader_source, session.shader_name);
  if (!update.ok) throw make_error(ErrorCode::kInvalidInput, "{}", update.error);
}

// The scene's sub-volumes and attributes as the renderer's layout. \error kInvalidInput
// with the renderer's message.
void apply_scene_layout(render::VolumeRenderer& renderer, const Scene& scene) {
  std::vector<std::uint32_t> ids;
  for (const auto& s : scene.subvolumes) ids.push_back(s.id);
  if (const auto update = renderer.set_scene_layout(ids, scene.attributes); !update.ok) {
    throw make_error(ErrorCode::kInvalidInput, "{}", update.error);
  }
}

}  // namespace

int run_offscreen(const ViewerArgs& args) {
  const auto [width, height] = cli::parse_image_size(args.size);
  auto context = render::HeadlessContext::create();
  spdlog::info("headless {}", context->description());
  ViewerSession session = open_session(args);
  const auto legend = apply_look(args, session);

  render::RenderSettings settings;
  settings.max_fragment_bytes = static_cast<std::size_t>(args.max_fragment_mib * 1048576.0);
  render::VolumeRenderer renderer(settings);
  apply_session_shader(renderer, session);
  view::ViewOptions options;
  options.vertical_exaggeration = session.exaggeration;
  options.lod.split_solid_angle_sr = args.lod_threshold_sr;
  options.lod.max_nodes = args.max_nodes;
  view::ViewController controller(*session.link, session.scene, options);
  apply_scene_layout(renderer, session.scene);
  const double aspect = double(width) / double(height);
  const auto cameras = offscreen_cameras(args, controller, aspect);
  const double advect_s = args.advect_seconds.value_or(0.0);
  const auto motions = advection_motions(args, session, controller, advect_s);

  render::OffscreenTarget target(width, height);
  const double time_s = view::seconds_since_first_step(controller.link().manifest(),
                                                       controller.time_step()) + advect_s;
  std::optional<view::SunAtTime> sun;
  if (args.sun == "time") {
    sun = view::sun_at_step(controller.link().placer().frame(), controller.link().manifest(),
                            controller.time_step(), advect_s);
    if (!sun) spdlog::info("the store's time axis or grid gives no real date or place: fixed sun");
  }
  const auto tracks_start = std::chrono::steady_clock::now();
  const auto tracks = tracks_at(session, args, controller, advect_s);
  const double track_window_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - tracks_start).count();
  const RunFacts run{session, controller, renderer, advect_s, sun, tracks, track_window_ms,
                     motions};
  render::LodCrossFade fade(args.lod_fade_ms);
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    double terrain_wait_ms = 0;
    std::shared_ptr<const view::TerrainFrame> terrain;
    if (session.terrain) {
      terrain = fully_loaded_terrain(*session.terrain, cameras[i], session.exaggeration, height,
                                     terrain_wait_ms);
    }
    auto inputs = render::frame_inputs(controller, cameras[i]);
    inputs.terrain = terrain;
    if (sun) inputs.sun_direction = sun->direction;
    else if (args.sun_fixed_direction) inputs.sun_direction = *args.sun_fixed_direction;
    inputs.tracks = tracks;
    inputs.time_seconds = time_s;
    inputs.motions = motions;
    const auto frame = render::render_complete_frame(
        controller, renderer, target, inputs,
        {.outline_cut = args.boxes, .fade = &fade, .fade_seconds = 1.0 / args.fps});
    const auto out = frame_path(args.out, i, cameras.size() > 1);
    if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
    if (legend) {
      auto image = frame.image;
      render::draw_colour_bar_legend(image, *legend);
      render::write_png(out, image);
    } else {
      render::write_png(out, frame.image);
    }
    if (args.json) {
      std::cout << frame_json_line(run, i, out, frame, terrain_wait_ms).dump() << std::endl;
    } else {
      const auto& s = frame.stats;
      spdlog::info("{}: {} nodes ({} with meshes, {} triangles), complete after {:.0f} ms, "
                   "rendered in {:.0f} ms, {:.1f} fragments per covered pixel",
                   out.string(), frame.cut_nodes, frame.nodes_with_mesh, s.triangles_drawn,
                   frame.wait_ms, frame.render_ms, s.fragments_per_covered_pixel());
    }
  }
  if (controller.failed_nodes() > 0) {
    spdlog::warn("{} nodes could not be extracted: {}", controller.failed_nodes(),
                 controller.last_error().value_or(""));
  }
  return 0;
}

}  // namespace strielad::view_cmd
