// SPDX-License-Identifier: Apache-2.0
// The viewer's link to a strielad-serve: one thread that owns the ServerClient, so the
// render loop never waits on the network. The render thread queues commands (cut
// differences, scene and time changes, stats requests) and takes events (placed node
// geometry, failures, errors, stats); the link thread sends, receives and places meshes
// in the world frame (view/node_geometry.h) meanwhile.
//
// Epochs: each scene or time change gets the next epoch number when it is queued, and
// every event carries the epoch in effect when the link received it. An event of an
// older epoch than the render thread's newest answers a superseded request. The link
// keeps a mirror of the cut the render thread sent, and after starting a generation
// sends the whole of it as `added` (formats/protocol.md: a generation starts with an
// empty cut), nearest first.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <unordered_map>
#include <variant>
#include <vector>

#include "client/server_client.h"
#include "lod/lod_cut.h"
#include "scene/scene.h"
#include "view/height_placement.h"
#include "view/node_geometry.h"

namespace strielad::view {

struct LinkEvent {
  enum class Kind {
    kResult,      // geometry of `node` (possibly empty)
    kFailed,      // the server could not extract `node` (message says why)
    kGeneration,  // the server started the epoch's generation
    kError,       // a request failed, or the connection is gone (fatal)
    kStats,       // message = the server's stats JSON
  };
  Kind kind = Kind::kResult;
  std::uint64_t epoch = 0;
  NodeId node = 0;
  std::shared_ptr<const NodeGeometry> geometry;
  std::string message;
  bool fatal = false;
};

struct LinkCounters {
  std::uint64_t results = 0;       // NodeResults received and placed
  std::uint64_t failed = 0;        // NodeFailed received
  std::uint64_t triangles = 0;     // triangles received (sub-volumes)
  std::uint64_t slice_triangles = 0;  // slice triangles received
  std::uint64_t bytes_received = 0;
  std::uint64_t stale_results = 0; // of older generations (the server must send none)
};

class ViewLink {
 public:
  // Takes over a client whose dataset is open. With heights from a variable
  // (view/height_placement.h) every scene is sent with that variable as one more
  // attribute (at the end, unless the scene carries it already) and the meshes are
  // placed by it. A curvilinear store's frame needs its GEOMETRY coordinates
  // (`horizontal_coordinates`, as GeometryPlacer). `shape`: the world's shape (the plane,
  // or the globe with its exaggeration placed into the meshes).
  explicit ViewLink(
      std::unique_ptr<client::ServerClient> client, HeightPlacement heights = {},
      std::shared_ptr<const format::HorizontalCoordinates> horizontal_coordinates = nullptr,
      PlacerShape shape = {});
  ~ViewLink();  // stops the thread; the client says Goodbye
  ViewLink(const ViewLink&) = delete;
  ViewLink& operator=(const ViewLink&) = delete;

  const format::Manifest& manifest() const { return manifest_; }
  const OctreeLayout& octree() const { return *octree_; }
  const GeometryPlacer& placer() const { return placer_; }

  // Queue a scene (and its time step) or a time step; returns the new epoch.
  std::uint64_t change_scene(const Scene& scene);
  std::uint64_t change_time(std::uint32_t step);
  void send_cut_diff(const lod::CutDiff& diff);
  void request_stats();

  // Events received so far, oldest first (at most `max`).
  std::vector<LinkEvent> take_events(std::size_t max = SIZE_MAX);
  LinkCounters counters() const;
  bool connected() const { return connected_.load(); }

 private:
  struct SceneCommand { Scene scene; std::uint64_t epoch; };
  struct TimeCommand { std::uint32_t step; std::uint64_t epoch; };
  struct StatsCommand {};
  using Command = std::variant<SceneCommand, TimeCommand, lod::CutDiff, StatsCommand>;

  void run();
  void execute(Command& command);
  void start_generation(const Scene* scene, std::uint32_t step, std::uint64_t epoch);
  void receive(protocol::Message& message);
  void push_event(LinkEvent event);

  std::unique_ptr<client::ServerClient> client_;
  format::Manifest manifest_;
  std::unique_ptr<OctreeLayout> octree_;
  GeometryPlacer placer_;

  // Link thread only.
  std::unordered_map<NodeId, float> cut_;  // the render thread's cut, as sent
  std::vector<std::uint32_t> slot_ids_;    // sub-volume id per slot, current scene
  int height_attribute_ = -1;              // the heights' attribute in the scene as sent
  std::uint64_t epoch_ = 0;                // in effect
  std::uint32_t step_ = 0;                 // time step of the generation in effect
  bool generation_active_ = false;

  mutable std::mutex mutex_;  // guards everything below
  std::condition_variable wake_;
  std::deque<Command> commands_;
  std::deque<LinkEvent> events_;
  std::uint64_t next_epoch_ = 0;
  LinkCounters counters_;
  bool stopping_ = false;

  std::atomic<bool> connected_{true};
  std::thread thread_;
};

}  // namespace strielad::view
