// SPDX-License-Identifier: Apache-2.0
// Encoded frames waiting to be written to one client, in order, by that client's
// writer thread. Producers check pending_bytes() to pause work for a slow reader; the
// session's reader waits in wait_until_at_most() before it reads the next request, so
// that no kind of reply can pile up without bound (ServerConfig::max_pending_send_bytes).
#pragma once

#include <atomic>
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
  // `total` (optional) is kept equal to the sum of every queue's pending bytes and
  // `peak` to the most any one queue held (ServerCounters).
  explicit SendQueue(std::atomic<std::int64_t>* total = nullptr,
                     std::atomic<std::uint64_t>* peak = nullptr)
      : total_(total), peak_(peak) {}
  ~SendQueue() { discard_pending(); }
  SendQueue(const SendQueue&) = delete;
  SendQueue& operator=(const SendQueue&) = delete;

  // False when the queue is closed (the frame is dropped).
  bool push(std::vector<std::byte> frame) {
    std::lock_guard lock(mutex_);
    if (closed_) return false;
    add_bytes_locked(static_cast<std::int64_t>(frame.size()));
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
    add_bytes_locked(-static_cast<std::int64_t>(frame.size()));
    return frame;
  }
  // After close, push fails and pop drains what is left (discard_pending drops it).
  void close() {
    std::lock_guard lock(mutex_);
    closed_ = true;
    ready_.notify_all();
    drained_.notify_all();
  }
  void discard_pending() {
    std::lock_guard lock(mutex_);
    frames_.clear();
    add_bytes_locked(-static_cast<std::int64_t>(bytes_));
  }
  std::uint64_t pending_bytes() const {
    std::lock_guard lock(mutex_);
    return bytes_;
  }
  // Blocks while more than `limit` bytes are pending and the queue is open (the writer
  // drains them, or closes the queue when the client is gone).
  void wait_until_at_most(std::uint64_t limit) {
    std::unique_lock lock(mutex_);
    drained_.wait(lock, [&] { return closed_ || bytes_ <= limit; });
  }

 private:
  void add_bytes_locked(std::int64_t delta) {
    bytes_ = static_cast<std::uint64_t>(static_cast<std::int64_t>(bytes_) + delta);
    if (total_) *total_ += delta;
    if (peak_ && delta > 0) {
      std::uint64_t seen = peak_->load();
      while (bytes_ > seen && !peak_->compare_exchange_weak(seen, bytes_)) {
      }
    }
    if (delta < 0) drained_.notify_all();
  }

  std::atomic<std::int64_t>* total_;
  std::atomic<std::uint64_t>* peak_;
  mutable std::mutex mutex_;
  std::condition_variable ready_, drained_;
  std::deque<std::vector<std::byte>> frames_;
  std::uint64_t bytes_ = 0;
  bool closed_ = false;
};

}  // namespace strielad::serve
