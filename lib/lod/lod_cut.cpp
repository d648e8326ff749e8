// SPDX-License-Identifier: Apache-2.0
#include "lod/lod_cut.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <functional>

#include "core/error.h"

namespace strielad::lod {
namespace {

// Priority and id in one integer ordered as (priority, id), for priority >= 0.
std::uint64_t pack(float priority, NodeId id) {
  return (std::uint64_t{std::bit_cast<std::uint32_t>(priority)} << 32) | id;
}

PrioritizedNode unpack(std::uint64_t key) {
  return PrioritizedNode{static_cast<NodeId>(key),
                         std::bit_cast<float>(static_cast<std::uint32_t>(key >> 32))};
}

// Sorts nearest first, ties by id (through packed keys: integer compares).
void sort_nearest_first(std::vector<PrioritizedNode>& nodes, std::vector<std::uint64_t>& keys) {
  keys.clear();
  for (const PrioritizedNode& n : nodes) keys.push_back(pack(n.priority, n.node));
  std::sort(keys.begin(), keys.end());
  for (std::size_t i = 0; i < keys.size(); ++i) nodes[i] = unpack(keys[i]);
}

}  // namespace

void validate_lod_options(const LodOptions& o) {
  if (!(o.split_solid_angle_sr >= 0) || !std::isfinite(o.split_solid_angle_sr)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "split_solid_angle_sr {} must be a finite number >= 0",
                     o.split_solid_angle_sr);
  }
  if (o.max_nodes < 1) {
    throw make_error(ErrorCode::kInvalidArgument, "max_nodes must be at least 1");
  }
  if (!(o.reprioritize_relative >= 0) || !std::isfinite(o.reprioritize_relative)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "reprioritize_relative {} must be a finite number >= 0",
                     o.reprioritize_relative);
  }
  if (!(o.hysteresis >= 0 && o.hysteresis < 1)) {
    throw make_error(ErrorCode::kInvalidArgument, "hysteresis {} must be in [0, 1)",
                     o.hysteresis);
  }
}

LodCut::LodCut(const OctreeLayout& layout, std::vector<WorldBox> boxes, LodOptions options)
    : options_(options), boxes_(std::move(boxes)) {
  validate_lod_options(options_);
  const std::size_t n = layout.node_count();
  if (boxes_.size() != n) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "{} node boxes given for an octree of {} nodes", boxes_.size(), n);
  }
  root_ = layout.root();
  centers_.reserve(n);
  radii_.reserve(n);
  for (const WorldBox& b : boxes_) {
    centers_.push_back(b.center());
    radii_.push_back(b.radius());
  }
  child_begin_.reserve(n + 1);
  child_ids_.reserve(n);
  for (NodeId id = 0; id < n; ++id) {
    child_begin_.push_back(static_cast<std::uint32_t>(child_ids_.size()));
    for (NodeId c : layout.children(id)) child_ids_.push_back(c);
  }
  child_begin_.push_back(static_cast<std::uint32_t>(child_ids_.size()));
  in_cut_.assign(n, 0);
  sent_.assign(n, 0.0f);
  mark_.assign(n, 0);
  was_split_.assign(n, 0);
}

void LodCut::compute_cut(const Camera& camera) {
  const Frustum frustum = view_frustum(camera);
  const Vec3 eye = camera.eye;
  const double split = options_.split_solid_angle_sr;
  const double keep_split = split * (1.0 - options_.hysteresis);
  stats_ = LodStats{};
  next_.clear();
  next_split_.clear();
  heap_.clear();

  // A visible node enters the cut directly unless it wants to be split; then it waits
  // in a min-heap of keys (the priority's float bits, monotonic for non-negative
  // floats, above the node id: ties go to the smaller id), so splits happen nearest
  // first and only they pay for ordering.
  auto consider = [&](NodeId id) {
    ++stats_.visited;
    const double distance = length(sub(centers_[id], eye));
    const auto priority = static_cast<float>(distance);
    if (child_begin_[id] != child_begin_[id + 1]) {
      const double omega = sphere_solid_angle(radii_[id], distance);
      if (omega > split || (was_split_[id] && omega > keep_split)) {
        heap_.push_back(pack(priority, id));
        std::push_heap(heap_.begin(), heap_.end(), std::greater<>());
        return;
      }
    }
    next_.push_back(PrioritizedNode{id, priority});
  };

  std::size_t count = 0;  // nodes in the heap plus nodes in the cut
  if (frustum.may_intersect(boxes_[root_])) {
    consider(root_);
    count = 1;
  } else {
    stats_.culled = 1;
  }
  NodeId visible[8];
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), std::greater<>());
    const PrioritizedNode n = unpack(heap_.back());
    heap_.pop_back();
    std::size_t shown = 0;
    for (std::uint32_t i = child_begin_[n.node]; i < child_begin_[n.node + 1]; ++i) {
      const NodeId c = child_ids_[i];
      if (frustum.may_intersect(boxes_[c])) {
        visible[shown++] = c;
      } else {
        ++stats_.culled;
      }
    }
    if (count - 1 + shown <= options_.max_nodes) {
      count = count - 1 + shown;
      for (std::size_t i = 0; i < shown; ++i) consider(visible[i]);
      next_split_.push_back(n.node);
      ++stats_.split;
    } else {
      stats_.capped = true;
      next_.push_back(n);
    }
  }

  for (NodeId id : split_nodes_) was_split_[id] = 0;
  for (NodeId id : next_split_) was_split_[id] = 1;
  split_nodes_.swap(next_split_);
}

CutDiff LodCut::update(const Camera& camera) {
  validate_camera(camera);
  compute_cut(camera);

  if (++epoch_ == 0) {  // wrapped: stale marks could equal the new epoch
    std::fill(mark_.begin(), mark_.end(), 0);
    epoch_ = 1;
  }
  for (const PrioritizedNode& n : next_) mark_[n.node] = epoch_;

  CutDiff diff;
  for (const PrioritizedNode& n : cut_) {
    if (mark_[n.node] != epoch_) {
      diff.removed.push_back(n.node);
      in_cut_[n.node] = 0;
    }
  }
  std::sort(diff.removed.begin(), diff.removed.end());
  const double rel = options_.reprioritize_relative;
  for (const PrioritizedNode& n : next_) {
    if (!in_cut_[n.node]) {
      in_cut_[n.node] = 1;
      sent_[n.node] = n.priority;
      diff.added.push_back(n);
    } else if (std::fabs(double{n.priority} - sent_[n.node]) > rel * sent_[n.node]) {
      sent_[n.node] = n.priority;
      diff.reprioritized.push_back(n);
    }
  }
  sort_nearest_first(diff.added, heap_);  // heap_ is free scratch now
  sort_nearest_first(diff.reprioritized, heap_);
  cut_.swap(next_);
  return diff;
}

CutDiff LodCut::full() {
  CutDiff diff;
  diff.added = cut_;
  sort_nearest_first(diff.added, heap_);
  for (const PrioritizedNode& n : cut_) sent_[n.node] = n.priority;
  return diff;
}

const WorldBox& LodCut::box(NodeId node) const {
  if (node >= boxes_.size()) {
    throw make_error(ErrorCode::kNotFound, "node {} does not exist (the octree has {} nodes)",
                     node, boxes_.size());
  }
  return boxes_[node];
}

void LodCut::reset() {
  for (const PrioritizedNode& n : cut_) in_cut_[n.node] = 0;
  cut_.clear();
  for (NodeId id : split_nodes_) was_split_[id] = 0;
  split_nodes_.clear();
}

}  // namespace strielad::lod
