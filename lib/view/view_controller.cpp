// SPDX-License-Identifier: Apache-2.0
#include "view/view_controller.h"

#include <chrono>
#include <cmath>
#include <unordered_set>

#include "core/error.h"

namespace strielad::view {

ViewController::ViewController(ViewLink& link, const Scene& scene, ViewOptions options)
    : link_(link), options_(options) {
  lod::validate_lod_options(options_.lod);
  const lod::WorldFrame& placed = link_.placer().frame();
  set_vertical_exaggeration(placed.globe() ? placed.vertical_exaggeration()
                                           : options_.vertical_exaggeration);
  set_scene(scene);
}

void ViewController::set_scene(const Scene& scene) {
  resolve_scene(scene, link_.manifest(), "scene");
  scene_ = scene;
  epoch_ = link_.change_scene(scene_);
  generation_started_ = false;
  meshes_.begin_generation();
}

void ViewController::set_time(std::uint32_t step) {
  if (step >= link_.manifest().time.values.size()) {
    throw make_error(ErrorCode::kNotFound, "time step {}: the store has {} steps", step,
                     link_.manifest().time.values.size());
  }
  if (step == scene_.time) return;
  scene_.time = step;
  epoch_ = link_.change_time(step);
  generation_started_ = false;
  meshes_.begin_generation();
}

void ViewController::set_vertical_exaggeration(double exaggeration) {
  if (!std::isfinite(exaggeration) || exaggeration <= 0) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "vertical exaggeration {} must be finite and > 0", exaggeration);
  }
  // The link's frame, at the new exaggeration (its horizontal placement is shared).
  frame_ = std::make_unique<lod::WorldFrame>(
      link_.placer().frame().with_exaggeration(exaggeration));
  options_.vertical_exaggeration = exaggeration;
  rebuild_cut();
}

void ViewController::set_lod_options(const lod::LodOptions& options) {
  lod::validate_lod_options(options);
  options_.lod = options;
  rebuild_cut();
}

void ViewController::rebuild_cut() {
  cut_rebuilt_ = cut_ != nullptr;
  auto boxes = lod::node_world_boxes(link_.octree(), *frame_);
  std::optional<double> globe_frame_height_km;
  if (frame_->globe()) {
    globe_frame_height_km = 0.0;
    for (std::size_t k = 0; k < frame_->dims().z; ++k) {
      globe_frame_height_km = std::max(*globe_frame_height_km, std::fabs(frame_->sample_world_z(k)));
    }
  }
  link_.placer().heights().widen_boxes(boxes, options_.vertical_exaggeration,
                                       globe_frame_height_km);
  cut_ = std::make_unique<lod::LodCut>(link_.octree(), std::move(boxes), options_.lod);
}

FrameCounters ViewController::update(const lod::Camera& camera, std::size_t max_events) {
  FrameCounters counters;
  const auto t0 = std::chrono::steady_clock::now();
  lod::CutDiff diff = cut_->update(camera);
  counters.cut_update_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  if (cut_rebuilt_) {
    // A new LodCut reports its whole cut as added: turn that into the difference to
    // what the server and the meshes have, so nodes that stay keep their meshes.
    cut_rebuilt_ = false;
    std::unordered_set<NodeId> now;
    for (const auto& a : diff.added) now.insert(a.node);
    lod::CutDiff real;
    for (const auto& [node, entry] : meshes_.entries()) {
      if (!now.contains(node)) real.removed.push_back(node);
    }
    std::sort(real.removed.begin(), real.removed.end());
    for (const auto& a : diff.added) {
      (meshes_.entries().contains(a.node) ? real.reprioritized : real.added).push_back(a);
    }
    diff = std::move(real);
  }
  counters.cut_changes = diff.added.size() + diff.removed.size() + diff.reprioritized.size();
  if (!diff.empty()) {
    meshes_.apply_cut_diff(diff);
    link_.send_cut_diff(diff);
  }
  auto events = link_.take_events(max_events);
  counters.events = events.size();
  for (auto& event : events) apply_event(event, counters);
  return counters;
}

void ViewController::apply_event(LinkEvent& event, FrameCounters& counters) {
  using Kind = LinkEvent::Kind;
  if (event.kind == Kind::kError) {
    last_error_ = event.message;
    if (event.fatal) connection_lost_ = true;
    return;
  }
  if (event.kind == Kind::kStats) {
    server_stats_ = std::move(event.message);
    return;
  }
  if (event.epoch != epoch_) {
    ++counters.superseded;
    return;
  }
  switch (event.kind) {
    case Kind::kGeneration:
      generation_started_ = true;
      break;
    case Kind::kResult:
      if (meshes_.accept(event.node, std::move(event.geometry))) ++counters.accepted;
      break;
    case Kind::kFailed:
      // Shown as empty, so the picture completes; the error stays visible.
      ++failed_nodes_;
      last_error_ = fmt::format("node {}: {}", event.node, event.message);
      meshes_.accept(event.node, nullptr);
      break;
    default:
      break;
  }
}

}  // namespace strielad::view
