// SPDX-License-Identifier: Apache-2.0
#include "serve/mpi_executor.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <stop_token>
#include <thread>

#include "core/error.h"
#include "serve/mpi_messages.h"

namespace strielad::serve {

using namespace std::chrono_literals;

struct MpiMaster::Pending {
  std::uint64_t id = 0;
  int rank = 0;
  bool done = false;       // the reply is in `output` / `loaded`
  bool abandoned = false;  // the caller returned without it; the reply is dropped
  NodeOutput output;
  std::size_t loaded = 0;
  std::condition_variable cv;
};

namespace {

// The worker rank a node belongs to: FNV-1a of the dataset name and the node, mixed.
int home_rank(const std::string& dataset, NodeId node, int workers) {
  std::uint64_t h = 1469598103934665603ull;
  for (const char c : dataset) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  for (int shift = 0; shift < 32; shift += 8) {
    h ^= (node >> shift) & 0xFFu;
    h *= 1099511628211ull;
  }
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdull;
  h ^= h >> 33;
  return 1 + static_cast<int>(h % static_cast<std::uint64_t>(workers));
}

[[noreturn]] void fatal(std::string_view what, const std::exception& e) {
  spdlog::critical("MPI rank 0: {}: {}; aborting every rank", what, e.what());
  MpiRuntime::abort(1);
}

}  // namespace

MpiMaster::MpiMaster(const MpiRuntime& runtime)
    : runtime_(runtime), workers_(static_cast<std::size_t>(runtime.size())) {
  if (runtime.rank() != 0 || runtime.size() < 2) {
    throw make_error(ErrorCode::kInternal, "MpiMaster on rank {} of {}", runtime.rank(),
                     runtime.size());
  }
  const int worker_count = runtime.size() - 1;
  int ready = 0;
  std::string failure;
  ErrorCode failure_code = ErrorCode::kInternal;
  PollBackoff backoff;
  auto next_report = std::chrono::steady_clock::now() + 30s;
  while (ready < worker_count) {
    std::optional<MpiChannel::Message> m = channel_.receive();
    if (!m) {
      if (std::chrono::steady_clock::now() > next_report) {
        spdlog::warn("MPI: still waiting for {} of {} worker ranks to start", worker_count - ready,
                     worker_count);
        next_report += 30s;
      }
      std::this_thread::sleep_for(backoff.next());
      continue;
    }
    backoff.reset();
    if (m->tag != mpi::kReady) {
      spdlog::error("MPI: unexpected message (tag {}) from rank {} before it was ready", m->tag,
                    m->source);
      continue;
    }
    mpi::WorkerReady r;
    try {
      r = mpi::decode_ready(m->bytes);
    } catch (const Error& e) {
      fatal("a worker's Ready message", e);
    }
    Worker& w = workers_[static_cast<std::size_t>(m->source)];
    w.host = r.host;
    w.threads = std::max(1u, r.threads);
    w.cache.budget = r.cache_budget;
    ++ready;
    if (r.error && failure.empty()) {
      failure = fmt::format("MPI rank {} on {}: {}", m->source, r.host, r.message);
      failure_code = *r.error;
    }
  }
  if (!failure.empty()) {
    stop_workers();
    throw make_error(failure_code, "{}", failure);
  }
  std::string ranks;
  for (int rank = 1; rank < runtime.size(); ++rank) {
    const Worker& w = workers_[static_cast<std::size_t>(rank)];
    ranks += fmt::format("{}{} on {} ({} threads)", rank > 1 ? ", " : "", rank, w.host, w.threads);
  }
  spdlog::info("MPI: {} ranks; rank 0 on {} serves clients, worker ranks {}", runtime.size(),
               runtime.host(), ranks);
}

MpiMaster::~MpiMaster() {
  try {
    stop_workers();
  } catch (const std::exception& e) {
    fatal("stopping the workers", e);
  }
}

unsigned MpiMaster::worker_threads() const {
  std::lock_guard lock(mutex_);
  unsigned total = 0;
  for (std::size_t rank = 1; rank < workers_.size(); ++rank) total += workers_[rank].threads;
  return total;
}

std::unique_ptr<NodeExecutor> MpiMaster::executor() {
  return std::make_unique<MpiNodeExecutor>(*this);
}

NodeOutput MpiMaster::execute(const NodeTask& task) {
  const std::shared_ptr<Pending> p = run_task(task, false, nullptr);
  return p ? std::move(p->output) : NodeOutput{};
}

std::size_t MpiMaster::prefetch(const NodeTask& task, const YieldCheck& should_yield) {
  const std::shared_ptr<Pending> p = run_task(task, true, &should_yield);
  return p ? p->loaded : 0;
}

BrickCacheStats MpiMaster::cache_stats() const {
  std::lock_guard lock(mutex_);
  BrickCacheStats sum;
  for (std::size_t rank = 1; rank < workers_.size(); ++rank) {
    const BrickCacheStats& c = workers_[rank].cache;
    sum.hits += c.hits;
    sum.misses += c.misses;
    sum.evictions += c.evictions;
    sum.bytes += c.bytes;
    sum.budget += c.budget;
    sum.entries += c.entries;
  }
  return sum;
}

int MpiMaster::place_locked(const NodeTask& task, bool may_steal) const {
  const int count = runtime_.size() - 1;
  const int home = home_rank(task.dataset, task.node, count);
  const Worker& h = workers_[static_cast<std::size_t>(home)];
  if (!may_steal || h.in_flight < h.threads) return home;
  int best = home;
  for (int i = 1; i < count; ++i) {
    const int rank = 1 + (home - 1 + i) % count;
    const Worker& w = workers_[static_cast<std::size_t>(rank)];
    if (w.in_flight >= w.threads) continue;
    if (best == home || w.in_flight < workers_[static_cast<std::size_t>(best)].in_flight) best = rank;
  }
  return best;
}

void MpiMaster::send_scene_locked(int rank, const NodeTask& task) {
  std::deque<std::uint64_t>& held = workers_[static_cast<std::size_t>(rank)].scenes;
  const std::uint64_t id = task.scene_source->id;
  if (std::find(held.begin(), held.end(), id) != held.end()) return;
  outbox_.push_back(
      {rank, mpi::kScene, mpi::encode(mpi::SceneDefinition{id, task.dataset, task.scene_source->json})});
  held.push_back(id);
  if (held.size() > mpi::kWorkerScenes) held.pop_front();  // as the worker forgets it
}

std::shared_ptr<MpiMaster::Pending> MpiMaster::run_task(const NodeTask& task, bool prefetch,
                                                       const YieldCheck* should_yield) {
  if (task.stop.stop_requested()) return nullptr;
  auto p = std::make_shared<Pending>();
  {
    std::lock_guard lock(mutex_);
    if (closed_) return nullptr;
    p->id = next_id_++;
    p->rank = place_locked(task, !prefetch);
    ++workers_[static_cast<std::size_t>(p->rank)].in_flight;
    pending_.emplace(p->id, p);
    mpi::TaskRequest request;
    request.id = p->id;
    request.kind = prefetch ? mpi::TaskKind::kPrefetch : mpi::TaskKind::kExtract;
    request.generation = task.generation;
    request.node = task.node;
    request.scene = task.scene_source->id;
    send_scene_locked(p->rank, task);
    outbox_.push_back({p->rank, mpi::kTask, mpi::encode(request)});
  }
  wake_.notify_one();
  if (wait_for_reply(*p, task, should_yield)) return p;
  return nullptr;
}

bool MpiMaster::wait_for_reply(Pending& p, const NodeTask& task, const YieldCheck* should_yield) {
  // The callback may run on the thread that requests the stop until this callback's
  // destructor returns, so it holds only what outlives this function: `p` is kept alive
  // by the caller (never the caller's shared_ptr itself: `return p` moves it).
  std::stop_callback on_stop(task.stop, [this, &p] {
    std::lock_guard lock(mutex_);
    p.cv.notify_all();
  });
  // Declared after the callback, so released before the callback (which locks) is removed.
  std::unique_lock lock(mutex_);
  const auto finished = [&] { return p.done || closed_ || task.stop.stop_requested(); };
  if (should_yield) {
    while (!p.cv.wait_for(lock, 1ms, finished)) {
      lock.unlock();
      const bool yield = (*should_yield)();  // takes the dispatcher's and sessions' locks
      lock.lock();
      if (yield) break;
    }
  } else {
    p.cv.wait(lock, finished);
  }
  if (p.done) return true;
  // Stopped (or yielding, or shutting down): return now; the worker's late reply only
  // frees its slot.
  p.abandoned = true;
  if (!closed_) {
    outbox_.push_back({p.rank, mpi::kCancel, mpi::encode_cancel(p.id)});
    wake_.notify_one();
  }
  return false;
}

void MpiMaster::communicate_while(const std::function<void()>& body) {
  std::exception_ptr error;
  std::thread runner([&] {
    try {
      body();
    } catch (...) {
      error = std::current_exception();
    }
    {
      std::lock_guard lock(mutex_);
      body_done_ = true;
    }
    wake_.notify_all();
  });
  try {
    pump();
    stop_workers();
  } catch (const std::exception& e) {
    fatal("talking to the workers", e);
  }
  runner.join();
  if (error) std::rethrow_exception(error);
}

void MpiMaster::pump() {
  PollBackoff backoff;
  for (;;) {
    std::deque<Outgoing> out;
    bool done = false;
    {
      std::lock_guard lock(mutex_);
      out.swap(outbox_);
      done = body_done_;
    }
    bool active = !out.empty();
    for (Outgoing& o : out) channel_.send(o.rank, o.tag, std::move(o.bytes));
    while (std::optional<MpiChannel::Message> m = channel_.receive()) {
      handle(std::move(*m));
      active = true;
    }
    if (done) return;
    if (active) backoff.reset();
    std::unique_lock lock(mutex_);
    if (!outbox_.empty() || body_done_) continue;
    // Replies are polled for while any is due; otherwise only a send can wake us.
    const bool expecting = !pending_.empty() || channel_.pending_sends() > 0;
    wake_.wait_for(lock, expecting ? backoff.next() : std::chrono::microseconds(50ms));
  }
}

void MpiMaster::handle(MpiChannel::Message message) {
  if (message.tag != mpi::kReply) {
    spdlog::error("MPI: unexpected message (tag {}) from rank {}", message.tag, message.source);
    return;
  }
  mpi::TaskReply reply = mpi::decode_reply(message.bytes);
  std::lock_guard lock(mutex_);
  Worker& w = workers_.at(static_cast<std::size_t>(message.source));
  if (w.in_flight > 0) --w.in_flight;
  w.cache = reply.cache;
  const auto it = pending_.find(reply.id);
  if (it == pending_.end()) {
    spdlog::error("MPI: reply from rank {} to unknown request {}", message.source, reply.id);
    return;
  }
  const std::shared_ptr<Pending> p = std::move(it->second);
  pending_.erase(it);
  if (p->abandoned) return;
  p->output.kind = reply.kind;
  p->output.frame = std::move(reply.frame);
  p->output.bricks = reply.bricks;
  p->output.slice_meshes = reply.slice_meshes;
  p->output.slice_triangles = reply.slice_triangles;
  p->loaded = static_cast<std::size_t>(reply.loaded);
  p->done = true;
  p->cv.notify_all();
}

void MpiMaster::stop_workers() {
  if (workers_stopped_) return;
  workers_stopped_ = true;
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
    outbox_.clear();
    for (auto& [id, p] : pending_) p->cv.notify_all();
  }
  const int worker_count = runtime_.size() - 1;
  for (int rank = 1; rank <= worker_count; ++rank) channel_.send(rank, mpi::kStop, {});
  // Each worker's kStopped comes after everything else it sent (MPI keeps the order of
  // one sender's messages), so once all are in no message to rank 0 is left in flight.
  int stopped = 0;
  PollBackoff backoff;
  auto next_report = std::chrono::steady_clock::now() + 10s;
  while (stopped < worker_count || channel_.progress() > 0) {
    if (std::optional<MpiChannel::Message> m = channel_.receive()) {
      backoff.reset();
      if (m->tag == mpi::kStopped) {
        ++stopped;
      } else if (m->tag == mpi::kReply) {
        handle(std::move(*m));  // a late reply: only its cache statistics count
      }
      continue;
    }
    if (std::chrono::steady_clock::now() > next_report) {
      spdlog::warn("MPI: waiting for {} of {} worker ranks to stop", worker_count - stopped,
                   worker_count);
      next_report += 10s;
    }
    std::this_thread::sleep_for(backoff.next());
  }
  spdlog::info("MPI: {} worker ranks stopped", worker_count);
}

}  // namespace strielad::serve
