// SPDX-License-Identifier: Apache-2.0
#include "serve/dispatcher.h"

#include <algorithm>

#include "serve/server_counters.h"
#include "serve/session.h"

namespace strielad::serve {

Dispatcher::Dispatcher(unsigned workers, NodeExecutor& executor, ServerCounters& counters,
                       bool prefetch)
    : workers_(std::max(1u, workers)),
      executor_(executor),
      counters_(counters),
      prefetch_(prefetch),
      parallelism_(oneapi::tbb::global_control::max_allowed_parallelism,
                   std::max<std::size_t>(
                       oneapi::tbb::global_control::active_value(
                           oneapi::tbb::global_control::max_allowed_parallelism),
                       workers_ + 1)),
      arena_(static_cast<int>(workers_), 0) {}

Dispatcher::~Dispatcher() {
  std::unique_lock lock(mutex_);
  sessions_.clear();
  idle_.wait(lock, [&] { return active_ == 0; });
}

void Dispatcher::attach(std::shared_ptr<Session> session) {
  std::lock_guard lock(mutex_);
  sessions_.push_back(std::move(session));
}

void Dispatcher::detach(const Session* session) {
  std::lock_guard lock(mutex_);
  std::erase_if(sessions_, [&](const auto& s) { return s.get() == session; });
}

void Dispatcher::notify() {
  std::lock_guard lock(mutex_);
  dirty_ = true;
  // Every idle worker: a whole cut update arrives with one notify. A worker that finds
  // nothing to take returns at once.
  while (active_ < workers_) {
    ++active_;
    arena_.enqueue([this] { worker_loop(); });
  }
}

bool Dispatcher::has_queued_work() const {
  std::lock_guard lock(mutex_);
  return std::any_of(sessions_.begin(), sessions_.end(),
                     [](const auto& s) { return s->has_queued_work(); });
}

std::optional<std::pair<std::shared_ptr<Session>, NodeTask>> Dispatcher::next_task(bool prefetch) {
  std::lock_guard lock(mutex_);
  const std::size_t n = sessions_.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = (round_robin_ + i) % n;
    const std::shared_ptr<Session>& session = sessions_[k];
    std::optional<NodeTask> task = prefetch ? session->take_prefetch() : session->take_task();
    if (task) {
      round_robin_ = k + 1;
      return std::make_pair(session, std::move(*task));
    }
  }
  return std::nullopt;
}

void Dispatcher::worker_loop() {
  for (;;) {
    {
      std::lock_guard lock(mutex_);
      dirty_ = false;
    }
    if (auto job = next_task(false)) {
      NodeOutput output = executor_.execute(job->second);
      job->first->complete(job->second, std::move(output));
      continue;
    }
    if (prefetch_) {
      if (auto job = next_task(true)) {
        ++counters_.prefetch_nodes;
        counters_.prefetch_bricks +=
            executor_.prefetch(job->second, [this] { return has_queued_work(); });
        continue;
      }
    }
    std::lock_guard lock(mutex_);
    if (dirty_) continue;
    if (--active_ == 0) idle_.notify_all();
    return;
  }
}

}  // namespace strielad::serve
