// SPDX-License-Identifier: Apache-2.0
// Which mesh the viewer shows for each node of its level-of-detail cut while results
// stream in (progressive updates):
// - a node that enters the cut shows nothing until its result arrives: no stale mesh,
//   not even one it had before it left the cut (meshes of nodes that leave are dropped);
// - on a change of sub-volumes or time step (begin_generation) every node keeps showing
//   its mesh, now stale, until the new generation's result for it replaces it;
// - a result for a node that is not in the cut is refused (it arrived after the node
//   left); an empty result (nothing inside, or skipped) is a current, empty node.
// The viewer decides whether a result belongs to the current generation (ViewLink
// epochs); this class only keeps the per-node state. Not thread-safe: the render
// thread owns it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <unordered_map>

#include "lod/lod_cut.h"
#include "view/node_geometry.h"

namespace strielad::view {

class ProgressiveMeshes {
 public:
  struct Entry {
    std::shared_ptr<const NodeGeometry> mesh;  // null: nothing to show
    bool current = false;  // mesh is the current generation's answer
  };

  // Nodes removed from the cut lose their mesh; added nodes start without one.
  void apply_cut_diff(const lod::CutDiff& diff);
  // Every node's mesh becomes stale (kept, shown, not current).
  void begin_generation();
  // The current generation's answer for `node` (null mesh: nothing inside). Returns
  // false, changing nothing, when the node is not in the cut.
  bool accept(NodeId node, std::shared_ptr<const NodeGeometry> mesh);
  void clear();

  const std::unordered_map<NodeId, Entry>& entries() const { return entries_; }
  std::size_t size() const { return entries_.size(); }
  std::size_t pending() const { return entries_.size() - current_; }  // not yet answered
  std::size_t stale_shown() const;  // not current but showing a mesh
  bool complete() const { return current_ == entries_.size(); }
  // Increases on every change of what is shown (the renderer re-syncs when it moved).
  std::uint64_t version() const { return version_; }

 private:
  std::unordered_map<NodeId, Entry> entries_;
  std::size_t current_ = 0;
  std::uint64_t version_ = 0;
};

}  // namespace strielad::view
