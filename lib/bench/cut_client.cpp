// SPDX-License-Identifier: Apache-2.0
#include "bench/cut_client.h"

#include "core/error.h"

namespace strielad::bench {

namespace {

std::vector<protocol::NodePriority> wire(const std::vector<lod::PrioritizedNode>& nodes) {
  std::vector<protocol::NodePriority> out;
  out.reserve(nodes.size());
  for (const auto& n : nodes) out.push_back({n.node, n.priority});
  return out;
}

}  // namespace

CutClient::CutClient(const net::Endpoint& server, const std::string& dataset, lod::LodOptions lod,
                     const std::string& name) {
  client::ClientOptions options;
  options.client_name = name;
  client_ = client::ServerClient::connect(server, options);
  const format::Manifest& manifest = client_->open_dataset(dataset);
  frame_ = std::make_unique<lod::WorldFrame>(manifest);
  cut_ = std::make_unique<lod::LodCut>(client_->octree(),
                                       lod::node_world_boxes(client_->octree(), *frame_), lod);
}

Clock::time_point CutClient::start_generation(bool scene_change, const Scene* scene,
                                              std::uint32_t step) {
  const Clock::time_point origin = Clock::now();
  const protocol::GenerationStarted started =
      scene_change ? client_->set_scene(*scene) : client_->set_time(step);
  generation_ = started.generation;
  origin_ = origin;
  answered_.clear();
  arrivals_.clear();
  generation_counters_ = {};
  const lod::CutDiff full = cut_->full();
  if (!full.added.empty()) client_->update_cut(wire(full.added), {}, {});
  return origin;
}

Clock::time_point CutClient::set_scene(const Scene& scene) { return start_generation(true, &scene, 0); }

Clock::time_point CutClient::set_time(std::uint32_t step) { return start_generation(false, nullptr, step); }

void CutClient::move(const lod::Camera& camera) {
  const lod::CutDiff diff = cut_->update(camera);
  if (diff.empty() || generation_ == 0) return;
  for (NodeId n : diff.removed) answered_.erase(n);
  client_->update_cut(wire(diff.added), diff.removed, wire(diff.reprioritized));
}

void CutClient::take(protocol::Message message) {
  const double t = std::chrono::duration<double>(Clock::now() - origin_).count();
  CutClientCounters delta;
  if (auto* r = std::get_if<protocol::NodeResult>(&message)) {
    if (r->generation != generation_) return;
    delta.results = 1;
    bool mesh = false, skipped = true;
    for (const auto& sv : r->subvolumes) {
      mesh |= sv.outcome == NodeOutcome::kMesh;
      skipped &= sv.outcome != NodeOutcome::kMesh && sv.outcome != NodeOutcome::kEmpty;
      delta.triangles += sv.mesh.triangles.size();
    }
    delta.meshes = mesh;
    delta.skipped = skipped;
    answered_.emplace(r->node, t);
    arrivals_.emplace_back(r->node, t);
  } else if (auto* f = std::get_if<protocol::NodeFailed>(&message)) {
    if (f->generation != generation_) return;
    delta.failed = 1;
    answered_.emplace(f->node, t);
    arrivals_.emplace_back(f->node, t);
  } else if (std::holds_alternative<protocol::ErrorMessage>(message)) {
    delta.errors = 1;
  }
  for (CutClientCounters* c : {&counters_, &generation_counters_}) {
    c->results += delta.results;
    c->meshes += delta.meshes;
    c->skipped += delta.skipped;
    c->failed += delta.failed;
    c->errors += delta.errors;
    c->triangles += delta.triangles;
  }
}

void CutClient::pump(std::chrono::milliseconds wait) {
  if (auto m = client_->wait(wait)) take(std::move(*m));
  while (auto m = client_->poll()) take(std::move(*m));
}

bool CutClient::wait_complete(std::chrono::milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  while (!complete()) {
    if (Clock::now() >= deadline) return false;
    if (!client_->connected()) {
      throw make_error(ErrorCode::kIo, "server connection lost: {}", client_->close_reason());
    }
    pump(std::chrono::milliseconds(20));
  }
  return true;
}

std::size_t CutClient::answered_in_cut() const {
  std::size_t n = 0;
  for (const auto& node : cut_->nodes()) n += answered_.contains(node.node);
  return n;
}

std::vector<double> CutClient::arrival_seconds() const {
  std::vector<double> out;
  for (const auto& [node, t] : arrivals_) {
    const auto it = answered_.find(node);
    if (it != answered_.end() && it->second == t) out.push_back(t);
  }
  return out;
}

}  // namespace strielad::bench
