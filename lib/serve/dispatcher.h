// SPDX-License-Identifier: Apache-2.0
// Runs the sessions' nodes on a oneTBB arena of N workers. A worker takes the most
// urgent node of the next session in round-robin order (so one client cannot starve
// another), at the moment it is free: work queued later but more urgent still goes
// first. When no session has queued work, idle workers prefetch the next time step of
// each cut, checking between bricks whether real work arrived.
#pragma once

#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/task_arena.h>

#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include "serve/node_executor.h"

namespace strielad::serve {

class Session;
struct ServerCounters;

class Dispatcher {
 public:
  Dispatcher(unsigned workers, NodeExecutor& executor, ServerCounters& counters, bool prefetch);
  ~Dispatcher();  // waits until every worker has returned

  void attach(std::shared_ptr<Session> session);
  void detach(const Session* session);
  // Something may be runnable: start idle workers.
  void notify();
  // Whether some session has queued work a worker could take now.
  bool has_queued_work() const;
  unsigned workers() const { return workers_; }

 private:
  void worker_loop();
  std::optional<std::pair<std::shared_ptr<Session>, NodeTask>> next_task(bool prefetch);

  const unsigned workers_;
  NodeExecutor& executor_;
  ServerCounters& counters_;
  const bool prefetch_;
  // Enough TBB worker threads for the arena (by default TBB keeps one fewer than the
  // hardware threads, which would leave a 2-worker arena with one thread).
  oneapi::tbb::global_control parallelism_;
  oneapi::tbb::task_arena arena_;
  std::condition_variable idle_;

  mutable std::mutex mutex_;  // guards everything below
  std::vector<std::shared_ptr<Session>> sessions_;
  std::size_t round_robin_ = 0;
  unsigned active_ = 0;
  bool dirty_ = false;  // notify() since a worker last looked
};

}  // namespace strielad::serve
