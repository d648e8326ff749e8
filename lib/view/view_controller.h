// SPDX-License-Identifier: Apache-2.0
// The viewer's per-frame logic without any graphics: the level-of-detail cut for the
// camera (lod/lod_cut.h), the differences sent to the server through the ViewLink, and
// the mesh shown per node (view/progressive_meshes.h). strielad-view's window loop and
// its headless renderer both drive one of these; tests drive it without a GPU.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "lod/camera.h"
#include "lod/lod_cut.h"
#include "lod/world_frame.h"
#include "scene/scene.h"
#include "view/progressive_meshes.h"
#include "view/view_link.h"

namespace strielad::view {

struct ViewOptions {
  lod::LodOptions lod;
  double vertical_exaggeration = lod::kDefaultVerticalExaggeration;
};

struct FrameCounters {
  std::size_t events = 0;        // link events taken this frame
  std::size_t accepted = 0;      // results shown this frame
  std::size_t superseded = 0;    // results of an older request, dropped
  std::size_t cut_changes = 0;   // nodes added + removed + reprioritized this frame
  double cut_update_ms = 0;      // LodCut::update
};

class ViewController {
 public:
  // Starts the first generation with `scene` (its time step included).
  // \error as set_scene.
  ViewController(ViewLink& link, const Scene& scene, ViewOptions options = {});

  // A new scene (sub-volumes, attributes, time): meshes go stale and the whole cut is
  // requested again. \error kNotFound / kInvalidInput for a scene the store cannot
  // answer (resolve_scene); nothing changes then.
  void set_scene(const Scene& scene);
  // A new time step, as set_scene. \error kNotFound for a step the store lacks.
  void set_time(std::uint32_t step);
  // \error kInvalidArgument for a value that is not finite and > 0. On the globe the
  // meshes keep the exaggeration placed into them when the link opens (view/node_geometry.h,
  // which the controller starts with), and the renderer's vertex shaders move them to
  // this one (render/wgs84_glsl.h globe_redrawn): no mesh is extracted or placed again.
  void set_vertical_exaggeration(double exaggeration);
  // The z scale the renderer applies: the exaggeration on the plane, 1 on the globe
  // (whose heights are drawn at frame().vertical_exaggeration()).
  double renderer_vertical_scale() const {
    return frame_->globe() ? 1.0 : options_.vertical_exaggeration;
  }
  // \error as lod::validate_lod_options.
  void set_lod_options(const lod::LodOptions& options);

  // Once per frame: updates the cut for `camera` (world frame at the current
  // exaggeration), sends the difference, and applies at most `max_events` arrived
  // events. Never waits for the network.
  FrameCounters update(const lod::Camera& camera, std::size_t max_events = 512);

  const ProgressiveMeshes& meshes() const { return meshes_; }
  const lod::LodCut& cut() const { return *cut_; }
  const lod::WorldFrame& frame() const { return *frame_; }
  const Scene& scene() const { return scene_; }
  std::uint32_t time_step() const { return scene_.time; }
  const ViewOptions& options() const { return options_; }
  ViewLink& link() { return link_; }
  const ViewLink& link() const { return link_; }

  // The current request is answered for every node of the cut.
  bool complete() const { return generation_started_ && meshes_.complete(); }
  std::uint64_t epoch() const { return epoch_; }
  // The last error the link reported (a failed request, a lost connection), if any.
  const std::optional<std::string>& last_error() const { return last_error_; }
  std::uint64_t failed_nodes() const { return failed_nodes_; }
  const std::string& server_stats_json() const { return server_stats_; }
  bool connection_lost() const { return connection_lost_; }

 private:
  void rebuild_cut();
  void apply_event(LinkEvent& event, FrameCounters& counters);

  ViewLink& link_;
  ViewOptions options_;
  Scene scene_;
  std::unique_ptr<lod::WorldFrame> frame_;
  std::unique_ptr<lod::LodCut> cut_;
  bool cut_rebuilt_ = false;  // the next update replaces the cut wholesale
  ProgressiveMeshes meshes_;
  std::uint64_t epoch_ = 0;
  bool generation_started_ = false;
  std::optional<std::string> last_error_;
  std::uint64_t failed_nodes_ = 0;
  std::string server_stats_;
  bool connection_lost_ = false;
};

}  // namespace strielad::view
