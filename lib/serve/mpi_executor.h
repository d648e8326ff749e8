// SPDX-License-Identifier: Apache-2.0
// Rank 0 of strielad-serve under MPI (docs/cluster.md): the Server
// speaks to the clients and schedules their nodes as always; its
// NodeExecutor (MpiNodeExecutor) ships each node to a worker rank (lib/serve/
// mpi_worker.h) and waits for the encoded frame. The thread that made the MpiRuntime
// makes every MPI call: it runs MpiMaster::communicate_while while the server runs on
// another thread, and the dispatcher's threads hand it messages through a queue.
//
// Placement: a node goes to the rank picked by a hash of (dataset, node), so that every
// time step and every client of that node meet the same brick cache (prefetching of the
// next step too); when that rank already runs as many tasks as it has threads and
// another has a free one, the task goes to the least busy one instead. Prefetches always
// go to the node's own rank. A generation's scene goes to a worker once, before its
// first task there (lib/serve/mpi_messages.h); tasks name it by its id.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "serve/mpi_runtime.h"
#include "serve/node_executor.h"

namespace strielad::serve {

class MpiMaster {
 public:
  // Waits until every worker rank has said it is ready (its thread count, its root).
  // \error kNotFound (or the worker's error) when a worker cannot serve, e.g. the root is
  // not on its file system; the workers are stopped before it is thrown.
  explicit MpiMaster(const MpiRuntime& runtime);
  // Stops the workers if communicate_while has not. On the MPI thread.
  ~MpiMaster();
  MpiMaster(const MpiMaster&) = delete;
  MpiMaster& operator=(const MpiMaster&) = delete;

  // Threads of all worker ranks together: as many dispatcher workers keep every rank busy.
  unsigned worker_threads() const;
  // The executor for the Server; it must not outlive this MpiMaster.
  std::unique_ptr<NodeExecutor> executor();

  // Runs `body` (the server's accept loop) on a new thread and the communication with
  // the workers on this one until `body` returns; then every task still waiting returns
  // kCancelled, the workers are stopped and their last messages drained. Rethrows what
  // `body` threw.
  void communicate_while(const std::function<void()>& body);

  // For MpiNodeExecutor (any thread).
  NodeOutput execute(const NodeTask& task);
  std::size_t prefetch(const NodeTask& task, const YieldCheck& should_yield);
  BrickCacheStats cache_stats() const;
  std::size_t ranks() const { return static_cast<std::size_t>(runtime_.size()); }

 private:
  struct Pending;
  struct Worker {
    std::string host;
    unsigned threads = 1;
    unsigned in_flight = 0;  // sent and not yet replied to (cancelled ones too)
    BrickCacheStats cache;   // as of its latest reply
    // Ids of the scenes it holds, oldest first (mirrors the worker's list: mpi_messages.h).
    std::deque<std::uint64_t> scenes;
  };
  struct Outgoing {
    int rank;
    int tag;
    std::vector<std::byte> bytes;
  };

  // Sends the task and waits for its reply, for a stop, or for `should_yield` (polled
  // when given). Returns the finished Pending, or nullptr when abandoned.
  std::shared_ptr<Pending> run_task(const NodeTask& task, bool prefetch,
                                    const YieldCheck* should_yield);
  // Waits for `p`'s reply, a stop of `task`, or `should_yield`; true when the reply came.
  // On false the task is marked abandoned and its cancel queued.
  bool wait_for_reply(Pending& p, const NodeTask& task, const YieldCheck* should_yield);
  int place_locked(const NodeTask& task, bool may_steal) const;
  // Queues the task's scene for `rank` unless the worker holds it already.
  void send_scene_locked(int rank, const NodeTask& task);
  void pump();  // the MPI loop, until body_done_
  void handle(MpiChannel::Message message);
  void stop_workers();

  const MpiRuntime& runtime_;
  MpiChannel channel_;  // MPI thread only
  bool workers_stopped_ = false;  // MPI thread only

  mutable std::mutex mutex_;  // guards everything below
  std::condition_variable wake_;  // the MPI thread: something to send, or stop
  std::vector<Worker> workers_;   // index = rank; [0] unused
  std::deque<Outgoing> outbox_;
  std::unordered_map<std::uint64_t, std::shared_ptr<Pending>> pending_;
  std::uint64_t next_id_ = 1;
  bool body_done_ = false;
  bool closed_ = false;  // no new task goes out; waiting ones return kCancelled
};

// The NodeExecutor of rank 0: every node runs on a worker rank through `master`.
class MpiNodeExecutor final : public NodeExecutor {
 public:
  explicit MpiNodeExecutor(MpiMaster& master) : master_(master) {}
  NodeOutput execute(const NodeTask& task) override { return master_.execute(task); }
  std::size_t prefetch(const NodeTask& task, const YieldCheck& should_yield) override {
    return master_.prefetch(task, should_yield);
  }
  // The worker ranks' caches summed, as of each one's latest reply.
  BrickCacheStats cache_stats() const override { return master_.cache_stats(); }
  std::size_t ranks() const override { return master_.ranks(); }

 private:
  MpiMaster& master_;
};

}  // namespace strielad::serve
