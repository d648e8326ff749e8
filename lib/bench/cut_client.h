// SPDX-License-Identifier: Apache-2.0
// A simulated viewer for the latency benchmark: the same level-of-detail cut the
// viewer uses (lib/lod), driven by cameras, its differences sent to a strielad-serve,
// and the arrival time of every node's answer recorded for the current generation.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "client/server_client.h"
#include "lod/lod_cut.h"
#include "lod/world_frame.h"
#include "scene/scene.h"

namespace strielad::bench {

using Clock = std::chrono::steady_clock;

struct CutClientCounters {
  std::uint64_t results = 0;   // NodeResult of the current generation at the time
  std::uint64_t meshes = 0;    // of which with at least one mesh
  std::uint64_t skipped = 0;   // of which every sub-volume skipped
  std::uint64_t failed = 0;    // NodeFailed
  std::uint64_t errors = 0;    // ErrorMessage
  std::uint64_t triangles = 0;  // received
};

class CutClient {
 public:
  // Connects, opens `dataset` and builds the cut over its octree.
  // \error as client::ServerClient.
  CutClient(const net::Endpoint& server, const std::string& dataset, lod::LodOptions lod,
            const std::string& name);

  client::ServerClient& client() { return *client_; }
  const lod::WorldFrame& frame() const { return *frame_; }
  const lod::LodCut& cut() const { return *cut_; }

  // A new generation: waits for the server's confirmation, then sends the whole cut.
  // Returns when the request was sent (the latency origin).
  Clock::time_point set_scene(const Scene& scene);
  Clock::time_point set_time(std::uint32_t step);

  // Moves the camera: updates the cut and sends its differences (nothing when none).
  void move(const lod::Camera& camera);

  // Takes every message that has arrived (waits up to `wait` for the first).
  void pump(std::chrono::milliseconds wait = std::chrono::milliseconds(0));
  // Pumps until every node of the cut has an answer of this generation; false on timeout.
  bool wait_complete(std::chrono::milliseconds timeout);

  std::size_t cut_size() const { return cut_->nodes().size(); }
  std::size_t answered_in_cut() const;
  bool complete() const { return answered_in_cut() == cut_size(); }
  // Seconds from the generation's origin to each answer of a node still in the cut, in
  // arrival order.
  std::vector<double> arrival_seconds() const;
  Clock::time_point origin() const { return origin_; }
  const CutClientCounters& counters() const { return counters_; }
  // The same counted since the current generation started.
  const CutClientCounters& generation_counters() const { return generation_counters_; }

 private:
  Clock::time_point start_generation(bool scene_change, const Scene* scene, std::uint32_t step);
  void take(protocol::Message message);

  std::unique_ptr<client::ServerClient> client_;
  std::unique_ptr<lod::WorldFrame> frame_;
  std::unique_ptr<lod::LodCut> cut_;
  std::uint32_t generation_ = 0;
  Clock::time_point origin_{};
  std::unordered_map<NodeId, double> answered_;  // node -> seconds since origin
  std::vector<std::pair<NodeId, double>> arrivals_;
  CutClientCounters counters_, generation_counters_;
};

}  // namespace strielad::bench
