// SPDX-License-Identifier: Apache-2.0
#include "viewer_session.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <tuple>
#include <filesystem>
#include <numbers>
#include <spdlog/spdlog.h>

#include "advect/integrators.h"
#include "core/error.h"
#include "core/file_io.h"
#include "scenery/dem_source.h"
#include "scenery/drape_image.h"
#include "net/socket.h"
#include "net/token_file.h"
#include "view/default_exaggeration.h"
#include "format/geometry_field.h"
#include "store/store.h"
#include "view/default_scene.h"
#include "view/height_placement.h"
#include "view/local_server.h"
#include "view/model_surface_dem.h"
#include "view/simulation_time.h"
#include "view/sun_direction.h"
#include "view/view_choices.h"

namespace strielad::view_cmd {

std::string read_text_file(const std::string& path) {
  const auto bytes = read_file_bytes(path);
  return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

namespace {

// The wind is read from a store directory on this machine: STORE, or --wind-store.
void open_advection(const ViewerArgs& args, ViewerSession& session) {
  const std::string path = !args.wind_store.empty() ? args.wind_store : args.store;
  if (path.empty()) {
    session.advection_status = "no wind: give --wind-store DIR (the served store's directory)";
    if (args.advect) throw make_error(ErrorCode::kInvalidArgument, "--advect with --connect "
                                      "needs --wind-store DIR to read the wind from");
    return;
  }
  view::AdvectionSettings settings;
  // On the globe the maps move meshes in longitude, latitude and height
  // (view/displacement_map.h).
  settings.shape = session.link->placer().frame().globe() ? lod::FrameShape::kGlobe
                                                          : lod::FrameShape::kPlane;
  settings.names = view::parse_wind_names(args.wind);
  settings.level = args.wind_level;
  settings.displacement.integrator.method = advect::parse_method(args.integrator);
  settings.displacement.integrator.step_s = args.advect_step_s;
  settings.displacement.integrator.rtol = args.advect_rtol;
  try {
    session.advection = std::make_unique<view::AdvectionWorker>(Store::open(path), settings);
    session.advection_status =
        fmt::format("wind {} from level {}", args.wind, session.advection->level());
  } catch (const Error& e) {
    if (args.advect) throw;
    session.advection_status = e.what();  // shown in the panel; advection is off
  }
}

// The exaggeration to start with and, for the log, where it comes from.
std::pair<double, std::string> starting_exaggeration(const ViewerArgs& args,
                                                     const lod::WorldFrame& frame) {
  if (args.exaggeration) {
    return {*args.exaggeration, fmt::format("{:g} (--exaggeration)", *args.exaggeration)};
  }
  if (!args.camera_file.empty()) {
    return {lod::kDefaultVerticalExaggeration,
            fmt::format("{:g} (a camera path's, formats/camera-path.md; --exaggeration to "
                        "change it)",
                        lod::kDefaultVerticalExaggeration)};
  }
  const auto extent = view::domain_extent(frame);
  const double chosen = view::default_vertical_exaggeration(extent);
  if (frame.globe() && chosen > view::kMaxGlobeDefaultExaggeration) {
    return {view::kMaxGlobeDefaultExaggeration,
            fmt::format("{:g} on the globe (at most {:g}, so that the atmosphere stays a shell "
                        "over the Earth; the plane's rule gives {})",
                        view::kMaxGlobeDefaultExaggeration, view::kMaxGlobeDefaultExaggeration,
                        view::describe_default_exaggeration(extent))};
  }
  return {chosen, view::describe_default_exaggeration(extent)};
}

lod::FrameShape frame_shape(const std::string& name) {
  if (name == "plane") return lod::FrameShape::kPlane;
  if (name == "globe") return lod::FrameShape::kGlobe;
  return lod::FrameShape::kAuto;
}

// How the first frame is lit, for the log.
std::string sun_choice(const ViewerArgs& args, const ViewerSession& session) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  if (args.sun == "time") {
    if (const auto sun = view::sun_at_step(session.link->placer().frame(), session.link->manifest(),
                                           session.scene.time)) {
      return fmt::format("{} (--sun time, step {})", view::describe_sun(*sun), session.scene.time);
    }
    const auto& frame = session.link->placer().frame();
    return fmt::format("fixed, the built-in light from the south-southeast, 54 degrees up: {}",
                       frame.on_earth() ? "the store's time axis gives no real date"
                                        : frame.no_earth_reason());
  }
  if (const auto& d = args.sun_fixed_direction) {
    return fmt::format("fixed, from the scene file: {:.1f} degrees up, azimuth {:.1f} degrees",
                       std::asin(std::clamp((*d)[2], -1.0, 1.0)) / kDeg,
                       std::fmod(std::atan2((*d)[0], (*d)[1]) / kDeg + 360.0, 360.0));
  }
  return "fixed, the built-in light from the south-southeast, 54 degrees up (--sun fixed)";
}

// The server's client: an in-process server for a local store (kept in the session), or
// a connection to --connect with --dataset opened. Names the dataset in the session.
std::unique_ptr<client::ServerClient> open_client(const ViewerArgs& args, ViewerSession& session) {
  std::unique_ptr<client::ServerClient> client;
  if (!args.store.empty()) {
    view::LocalServerOptions options;
    options.threads = args.threads;
    options.cache_bytes = static_cast<std::uint64_t>(args.cache_mib * 1048576.0);
    auto local = view::open_local_store(args.store, options);
    session.server = std::move(local.server);
    client = std::move(local.client);
    session.dataset_name = args.store;
  } else {
    client::ClientOptions options;
    options.client_name = "strielad-view";
    if (!args.token_file.empty()) options.token = net::read_token_file(args.token_file);
    client = client::ServerClient::connect(net::parse_endpoint(args.connect, "--connect"), options);
    client->open_dataset(args.dataset);
    session.dataset_name = args.connect + "/" + args.dataset;
  }
  return client;
}

// The true sun needs a place on the Earth: refused when asked for, else the fixed light
// with a warning.
void check_true_sun_placeable(const ViewerArgs& args, const lod::WorldFrame& frame) {
  if (frame.on_earth() || args.sun != "time") return;
  if (args.sun_given || args.sun_time_asked) {
    throw make_error(ErrorCode::kUnsupported, "{}: the true sun cannot be placed: {}",
                     args.sun_given ? "--sun time" : "the scene's sun {\"mode\": \"time\"}",
                     frame.no_earth_reason());
  }
  spdlog::warn("the true sun cannot be placed ({}): lit by the fixed light",
               frame.no_earth_reason());
}

// --tracks: the flight tracks, which need real dates and a place on the Earth.
std::shared_ptr<const geo::FlightTracks> open_tracks(const ViewerArgs& args,
                                                     const format::Manifest& manifest,
                                                     const lod::WorldFrame& frame) {
  if (!view::step_julian_day(manifest, 0)) {
    throw make_error(ErrorCode::kUnsupported,
                     "--tracks {}: the store's time axis '{}' (units '{}', calendar '{}') has "
                     "no real date to place the tracks in time",
                     args.tracks_file, manifest.time.name, manifest.time.units,
                     manifest.time.calendar);
  }
  if (!frame.on_earth()) {
    throw make_error(ErrorCode::kUnsupported, "--tracks {}: flight tracks cannot be placed: {}",
                     args.tracks_file, frame.no_earth_reason());
  }
  auto tracks = std::make_shared<const geo::FlightTracks>(geo::load_flight_tracks(args.tracks_file));
  spdlog::info("{}: {} flight tracks, {} position reports", args.tracks_file,
               tracks->tracks.size(), tracks->reports);
  return tracks;
}

// --terrain: the DEM's tiles (loaded on their own thread), with the drape image of
// --terrain-image.
std::unique_ptr<view::TerrainTiles> open_terrain(const ViewerArgs& args,
                                                 const lod::WorldFrame& frame,
                                                 bool round_the_earth) {
  if (!frame.on_earth()) {
    throw make_error(ErrorCode::kUnsupported, "--terrain {}: terrain cannot be placed: {}",
                     args.terrain_file, frame.no_earth_reason());
  }
  std::shared_ptr<const geo::DemSource> dem = geo::open_dem(args.terrain_file, args.terrain_var);
  std::shared_ptr<const geo::DrapeImage> drape;
  if (!args.terrain_image.empty()) {
    drape = std::make_shared<const geo::DrapeImage>(args.terrain_image);
    spdlog::info("terrain drape image {}", drape->describe());
  }
  view::TerrainOptions options;
  options.error_pixels = args.terrain_error;
  options.cache_bytes = static_cast<std::size_t>(args.terrain_cache_mib * 1048576.0);
  options.round_the_earth = round_the_earth;
  return std::make_unique<view::TerrainTiles>(std::move(dem), frame, options, std::move(drape));
}

}  // namespace

ViewerSession open_session(const ViewerArgs& args) {
  ViewerSession session;
  std::unique_ptr<client::ServerClient> client = open_client(args, session);
  const format::Manifest manifest = client->manifest();
  session.scene = args.scene_file.empty() ? view::default_scene(manifest)
                                          : load_scene_file(args.scene_file);
  if (args.time) session.scene.time = *args.time;
  resolve_scene(session.scene, manifest,
                args.scene_file.empty() ? std::string("default scene") : args.scene_file);
  if (!args.shader_file.empty()) {
    session.shader_source = read_text_file(args.shader_file);
    session.shader_name = args.shader_file;
  } else {
    session.shader_name = "built-in clouds.glsl";
  }
  // Heights from a geopotential variable or a terrain-following geometry field need the
  // store's index for the node boxes (and the field's centre column for the frame): a
  // local store is opened for them.
  std::shared_ptr<const Store> local_store;
  if (!args.store.empty() && (manifest.z.kind == AxisKind::kPressure || manifest.geometry)) {
    local_store = Store::open(args.store);
  }
  if (format::is_curvilinear(manifest) && !local_store) {
    throw make_error(ErrorCode::kUnsupported,
                     "{}: a curvilinear store ('{}' / '{}') is viewed on its own machine for now "
                     "(strielad-view STORE): its columns are placed by the store's GEOMETRY "
                     "file, which the server does not send",
                     session.dataset_name, manifest.geometry->horizontal.lon_variable,
                     manifest.geometry->horizontal.lat_variable);
  }
  if (format::has_geometry_field(manifest) && !local_store) {
    throw make_error(ErrorCode::kUnsupported,
                     "{}: a terrain-following store (geometry field '{}') is viewed on its own "
                     "machine for now (strielad-view STORE): its vertices are placed by the "
                     "field, and the node boxes and vertical map need the store's files",
                     session.dataset_name, format::geometry_field_name(manifest));
  }
  view::HeightPlacement heights = view::choose_height_placement(manifest, local_store.get());
  session.vertical_placement = heights.description;
  auto coordinates =
      format::is_curvilinear(manifest) ? local_store->horizontal_coordinates() : nullptr;
  // The shape and the exaggeration first: the globe's meshes carry the exaggeration.
  const lod::WorldFrame probe(
      manifest, lod::WorldFrameOptions{.vertical_exaggeration = 1.0, .shape = frame_shape(args.shape)},
      heights.level_heights_m, coordinates);
  std::string exaggeration_rule;
  std::tie(session.exaggeration, exaggeration_rule) = starting_exaggeration(args, probe);
  session.link = std::make_unique<view::ViewLink>(
      std::move(client), std::move(heights), std::move(coordinates),
      view::PlacerShape{.shape = frame_shape(args.shape),
                        .globe_exaggeration = session.exaggeration});
  const lod::WorldFrame& frame = session.link->placer().frame();
  spdlog::info("world frame: {}{}", frame.describe_horizontal(),
               frame.globe() ? fmt::format(", on the WGS84 globe (wider than {:g} degrees or "
                                           "--shape globe)",
                                           lod::kGlobeMinExtentDeg)
                             : std::string());
  spdlog::info("vertical placement: {}", session.vertical_placement);
  check_true_sun_placeable(args, frame);
  view::log_view_choices({.default_scene = args.scene_file.empty() ? std::optional<Scene>(session.scene)
                                                                   : std::nullopt,
                          .exaggeration = exaggeration_rule,
                          .sun = sun_choice(args, session)});
  open_advection(args, session);
  if (!args.tracks_file.empty()) {
    session.tracks = open_tracks(args, manifest, frame);
  }
  if (!args.terrain_file.empty()) {
    session.terrain = open_terrain(args, frame, manifest.x.periodic);
  } else if (local_store && manifest.geometry && manifest.geometry->surface && frame.on_earth()) {
    // The model's own surface as the default terrain.
    auto dem = std::make_shared<const view::ModelSurfaceDem>(
        manifest, frame, local_store->horizontal_coordinates(), session.dataset_name);
    view::TerrainOptions options;
    options.error_pixels = args.terrain_error;
    options.cache_bytes = static_cast<std::size_t>(args.terrain_cache_mib * 1048576.0);
    options.round_the_earth = manifest.x.periodic;
    spdlog::info("terrain: {}", dem->describe());
    session.terrain = std::make_unique<view::TerrainTiles>(std::move(dem), frame, options);
  }
  spdlog::info("{}: {} x {} x {} grid, {} variables, {} time steps, {} octree nodes",
               session.dataset_name, manifest.x.size(), manifest.y.size(), manifest.z.size(),
               manifest.variables.size(), manifest.time.values.size(),
               session.link->octree().node_count());
  return session;
}

ViewerArgs with_scene_settings(ViewerArgs args) {
  if (args.scene_file.empty()) return args;
  const Scene scene = load_scene_file(args.scene_file);
  const std::filesystem::path dir = std::filesystem::path(args.scene_file).parent_path();
  const auto beside_scene = [&dir](const std::string& path) {
    const std::filesystem::path p(path);
    return (p.is_absolute() ? p : dir / p).lexically_normal().string();
  };
  if (scene.terrain && args.terrain_file.empty()) {
    args.terrain_file = beside_scene(scene.terrain->dem);
    if (args.terrain_var.empty()) args.terrain_var = scene.terrain->var;
    if (args.terrain_image.empty() && !scene.terrain->image.empty()) {
      args.terrain_image = beside_scene(scene.terrain->image);
    }
  }
  if (scene.trajectories && args.tracks_file.empty()) {
    args.tracks_file = beside_scene(scene.trajectories->file);
    args.track_minutes = scene.trajectories->minutes;
  }
  if (scene.sun && scene.sun->from_time && !args.sun_given) args.sun_time_asked = true;
  if (scene.sun && !scene.sun->from_time && !args.sun_given) {
    constexpr double kRad = std::numbers::pi / 180.0;
    const double el = scene.sun->elevation_deg * kRad, az = scene.sun->azimuth_deg * kRad;
    args.sun = "fixed";
    args.sun_fixed_direction = Vec3{std::sin(az) * std::cos(el), std::cos(az) * std::cos(el),
                                         std::sin(el)};
  }
  return args;
}

std::shared_ptr<const view::TrackLines> tracks_at(const ViewerSession& session,
                                                  const ViewerArgs& args,
                                                  const view::ViewController& controller,
                                                  double seconds_after) {
  if (!session.tracks) return nullptr;
  const auto jd =
      view::step_julian_day(session.link->manifest(), controller.time_step(), seconds_after);
  if (!jd) return nullptr;
  const double now = (*jd - session.tracks->reference_julian_day) * 86400.0;
  const lod::WorldFrame& frame =
      controller.frame().globe() ? controller.frame() : session.link->placer().frame();
  return std::make_shared<const view::TrackLines>(
      view::window_tracks(*session.tracks, now, args.track_minutes * 60.0, frame));
}

}  // namespace strielad::view_cmd
