// SPDX-License-Identifier: Apache-2.0
#include "serve/work_queue.h"

#include <utility>

namespace strielad::serve {

std::size_t WorkQueue::start_generation(std::uint32_t generation) {
  const std::size_t dropped = heap_.size();
  heap_.clear();
  slot_of_.clear();
  generation_ = generation;
  return dropped;
}

bool WorkQueue::add(NodeId node, float priority) {
  if (slot_of_.contains(node)) return false;
  heap_.push_back({});
  place(heap_.size() - 1, Entry{node, priority, next_sequence_++});
  sift_up(heap_.size() - 1);
  return true;
}

bool WorkQueue::remove(NodeId node) {
  const auto it = slot_of_.find(node);
  if (it == slot_of_.end()) return false;
  erase_slot(it->second);
  return true;
}

bool WorkQueue::reprioritize(NodeId node, float priority) {
  const auto it = slot_of_.find(node);
  if (it == slot_of_.end()) return false;
  const std::size_t slot = it->second;
  const float old = heap_[slot].priority;
  heap_[slot].priority = priority;
  if (priority < old) {
    sift_up(slot);
  } else {
    sift_down(slot);
  }
  return true;
}

std::optional<float> WorkQueue::priority(NodeId node) const {
  const auto it = slot_of_.find(node);
  if (it == slot_of_.end()) return std::nullopt;
  return heap_[it->second].priority;
}

std::optional<WorkItem> WorkQueue::top() const {
  if (heap_.empty()) return std::nullopt;
  return WorkItem{heap_.front().node, generation_, heap_.front().priority};
}

std::optional<WorkItem> WorkQueue::pop() {
  std::optional<WorkItem> item = top();
  if (item) erase_slot(0);
  return item;
}

void WorkQueue::place(std::size_t slot, Entry entry) {
  slot_of_[entry.node] = slot;
  heap_[slot] = entry;
}

void WorkQueue::sift_up(std::size_t slot) {
  Entry entry = heap_[slot];
  while (slot > 0) {
    const std::size_t parent = (slot - 1) / 2;
    if (!before(entry, heap_[parent])) break;
    place(slot, heap_[parent]);
    slot = parent;
  }
  place(slot, entry);
}

void WorkQueue::sift_down(std::size_t slot) {
  Entry entry = heap_[slot];
  const std::size_t n = heap_.size();
  for (;;) {
    std::size_t child = 2 * slot + 1;
    if (child >= n) break;
    if (child + 1 < n && before(heap_[child + 1], heap_[child])) ++child;
    if (!before(heap_[child], entry)) break;
    place(slot, heap_[child]);
    slot = child;
  }
  place(slot, entry);
}

void WorkQueue::erase_slot(std::size_t slot) {
  slot_of_.erase(heap_[slot].node);
  const std::size_t last = heap_.size() - 1;
  if (slot != last) {
    const Entry moved = heap_[last];
    heap_.pop_back();
    place(slot, moved);
    sift_up(slot);
    sift_down(slot_of_.at(moved.node));
  } else {
    heap_.pop_back();
  }
}

}  // namespace strielad::serve
