// SPDX-License-Identifier: Apache-2.0
#include "view/progressive_meshes.h"

namespace strielad::view {

void ProgressiveMeshes::apply_cut_diff(const lod::CutDiff& diff) {
  for (const NodeId node : diff.removed) {
    const auto it = entries_.find(node);
    if (it == entries_.end()) continue;
    if (it->second.current) --current_;
    entries_.erase(it);
    ++version_;
  }
  for (const auto& added : diff.added) {
    // A node re-entering the cut starts over: whatever it showed before is gone.
    auto [it, inserted] = entries_.try_emplace(added.node);
    if (!inserted) {
      if (it->second.current) --current_;
      it->second = Entry{};
    }
    ++version_;
  }
}

void ProgressiveMeshes::begin_generation() {
  for (auto& [node, entry] : entries_) entry.current = false;
  current_ = 0;
  ++version_;
}

bool ProgressiveMeshes::accept(NodeId node, std::shared_ptr<const NodeGeometry> mesh) {
  const auto it = entries_.find(node);
  if (it == entries_.end()) return false;
  if (!it->second.current) ++current_;
  it->second.current = true;
  it->second.mesh = (mesh && !mesh->empty()) ? std::move(mesh) : nullptr;
  ++version_;
  return true;
}

void ProgressiveMeshes::clear() {
  entries_.clear();
  current_ = 0;
  ++version_;
}

std::size_t ProgressiveMeshes::stale_shown() const {
  std::size_t n = 0;
  for (const auto& [node, entry] : entries_) n += (!entry.current && entry.mesh) ? 1 : 0;
  return n;
}

}  // namespace strielad::view
