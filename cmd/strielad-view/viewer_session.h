// SPDX-License-Identifier: Apache-2.0
// What every strielad-view run starts with: the server (in-process for a local store, or
// remote), the link thread, the first scene, and the user's shader text.
#pragma once

#include <memory>
#include <string>
#include <utility>

#include "scenery/flight_tracks.h"
#include "scene/scene.h"
#include "serve/server.h"
#include "view/advection_worker.h"
#include "view/terrain_tiles.h"
#include "view/track_window.h"
#include "view/view_controller.h"
#include "view/view_link.h"
#include "viewer_args.h"

namespace strielad::view_cmd {

struct ViewerSession {
  std::unique_ptr<serve::Server> server;  // in-process only; destroyed after the link
  std::unique_ptr<view::ViewLink> link;
  std::string dataset_name;
  Scene scene;
  // The vertical exaggeration to start with: --exaggeration, or the default the domain
  // or the camera path gives (logged with its rule).
  double exaggeration = lod::kDefaultVerticalExaggeration;
  std::string shader_name;   // the file, or "built-in clouds.glsl"
  std::string shader_source; // empty: the built-in one
  // Wind advection: null when the store has no wind (advection_status says why).
  std::unique_ptr<view::AdvectionWorker> advection;
  std::string advection_status;
  // Flight tracks (--tracks), null when none.
  std::shared_ptr<const geo::FlightTracks> tracks;
  // Terrain (--terrain), null when none; tiles load on its own thread.
  std::unique_ptr<view::TerrainTiles> terrain;
  // How the meshes' heights are placed (view/height_placement.h), for the panel and log.
  std::string vertical_placement;
};

// The tracks to draw at the controller's time step plus `seconds_after` (null without
// --tracks), placed as the renderer draws them: on the plane at exaggeration 1 (the
// renderer scales z), on the globe at the controller's exaggeration.
std::shared_ptr<const view::TrackLines> tracks_at(const ViewerSession& session,
                                                  const ViewerArgs& args,
                                                  const view::ViewController& controller,
                                                  double seconds_after);

// \error kNotFound / kInvalidInput naming the store, scene or shader file at fault;
// kIo when the server cannot be reached; with --advect, the errors of
// view::AdvectionWorker (a store without wind, a wind level outside the octree).
ViewerSession open_session(const ViewerArgs& args);

// The scene file's geographic settings (format version 2: "terrain", "sun",
// "trajectories") filled in where no flag gave them: flags win, paths are taken relative
// to the scene file. Without a scene file, `args` unchanged. \error as load_scene_file.
ViewerArgs with_scene_settings(ViewerArgs args);

// The shader file's text. \error kNotFound / kIo naming the file.
std::string read_text_file(const std::string& path);

}  // namespace strielad::view_cmd
