// SPDX-License-Identifier: Apache-2.0
// The pending extraction work of one client: octree nodes ordered by priority (smaller
// first, the camera distance of the paper; equal priorities in insertion order), with
// insert, remove and reprioritize in O(log n) through an indexed binary heap. Every item
// belongs to the queue's current generation: starting a new generation drops them all.
// Not thread-safe: the owning session serialises access.
#pragma once

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "octree/octree_layout.h"

namespace strielad::serve {

struct WorkItem {
  NodeId node = 0;
  std::uint32_t generation = 0;
  float priority = 0;
  friend bool operator==(const WorkItem&, const WorkItem&) = default;
};

class WorkQueue {
 public:
  std::uint32_t generation() const { return generation_; }
  // Drops every pending item and makes `generation` current. Returns how many were dropped.
  std::size_t start_generation(std::uint32_t generation);

  // False (and no change) when the node is already queued.
  bool add(NodeId node, float priority);
  // False when the node is not queued.
  bool remove(NodeId node);
  bool reprioritize(NodeId node, float priority);

  bool contains(NodeId node) const { return slot_of_.contains(node); }
  std::optional<float> priority(NodeId node) const;
  std::size_t size() const { return heap_.size(); }
  bool empty() const { return heap_.empty(); }

  // The most urgent item, without removing it.
  std::optional<WorkItem> top() const;
  // Removes and returns the most urgent item.
  std::optional<WorkItem> pop();

 private:
  struct Entry {
    NodeId node;
    float priority;
    std::uint64_t sequence;  // insertion order breaks ties
  };
  static bool before(const Entry& a, const Entry& b) {
    return a.priority < b.priority || (a.priority == b.priority && a.sequence < b.sequence);
  }
  void place(std::size_t slot, Entry entry);
  void sift_up(std::size_t slot);
  void sift_down(std::size_t slot);
  void erase_slot(std::size_t slot);

  std::vector<Entry> heap_;
  std::unordered_map<NodeId, std::size_t> slot_of_;
  std::uint32_t generation_ = 0;
  std::uint64_t next_sequence_ = 0;
};

}  // namespace strielad::serve
