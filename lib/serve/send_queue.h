// SPDX-License-Identifier: Apache-2.0
// Encoded frames waiting to be written to one client, in order, by that client's
// writer thread. Producers check pending_bytes() to pause work for a slow reader.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <vector>

namespace strielad::serve {

class SendQueue {
 public:
  // False when the queue is closed (the frame is dropped).
  bool push(std::vector<std::byte> frame) {
    std::lock_guard lock(mutex_);
    if (closed_) return false;
    bytes_ += frame.size();
    frames_.push_back(std::move(frame));
    ready_.notify_one();
    return true;
  }
  // Blocks for the next frame; nullopt once closed and drained.
  std::optional<std::vector<std::byte>> pop() {
    std::unique_lock lock(mutex_);
    ready_.wait(lock, [&] { return closed_ || !frames_.empty(); });
    if (frames_.empty()) return std::nullopt;
    std::vector<std::byte> frame = std::move(frames_.front());
    frames_.pop_front();
    bytes_ -= frame.size();
    return frame;
  }
  // After close, push fails and pop drains what is left (discard_pending drops it).
  void close() {
    std::lock_guard lock(mutex_);
    closed_ = true;
    ready_.notify_all();
  }
  void discard_pending() {
    std::lock_guard lock(mutex_);
    frames_.clear();
    bytes_ = 0;
  }
  std::uint64_t pending_bytes() const {
    std::lock_guard lock(mutex_);
    return bytes_;
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<std::vector<std::byte>> frames_;
  std::uint64_t bytes_ = 0;
  bool closed_ = false;
};

}  // namespace strielad::serve
