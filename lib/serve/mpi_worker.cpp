// SPDX-License-Identifier: Apache-2.0
#include "serve/mpi_worker.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

#include "core/error.h"
#include "protocol/message_codec.h"
#include "serve/client_error_text.h"
#include "serve/dataset_registry.h"
#include "serve/mpi_messages.h"
#include "serve/node_executor.h"
#include "store/brick_cache.h"
#include "store/store.h"

namespace strielad::serve {

namespace {

// An error message as a NodeFailed may carry it (protocol::kMaxMessageTextBytes).
std::string clipped(std::string text) {
  if (text.size() <= protocol::kMaxMessageTextBytes) return text;
  text.resize(protocol::kMaxMessageTextBytes - 3);
  while (!text.empty() && (static_cast<unsigned char>(text.back()) & 0xC0) == 0x80) text.pop_back();
  if (!text.empty() && (static_cast<unsigned char>(text.back()) & 0x80)) text.pop_back();
  return text + "...";
}

// A scene rank 0 sent (mpi::SceneDefinition), parsed and resolved by the first task that
// needs it; the tasks after it share the result.
class WorkerScene {
 public:
  explicit WorkerScene(mpi::SceneDefinition definition) : definition_(std::move(definition)) {}
  const std::string& dataset() const { return definition_.dataset; }
  // \error the scene's parse and resolve errors (then the next task tries again).
  std::shared_ptr<const ResolvedScene> resolved(const Store& store) {
    std::lock_guard lock(mutex_);
    if (!resolved_) {
      const Scene scene = parse_scene(definition_.scene_json, "scene");
      resolved_ = std::make_shared<const ResolvedScene>(resolve_scene(scene, store.manifest(), "scene"));
    }
    return resolved_;
  }

 private:
  const mpi::SceneDefinition definition_;
  std::mutex mutex_;
  std::shared_ptr<const ResolvedScene> resolved_;
};

class Worker {
 public:
  Worker(const MpiRuntime& runtime, const MpiWorkerOptions& options)
      : runtime_(runtime),
        threads_(options.threads ? options.threads
                                 : std::max(1u, std::thread::hardware_concurrency())),
        cache_(options.cache_bytes) {
    try {
      datasets_.emplace(options.root, options.direct_reads);
    } catch (const Error& e) {
      error_ = e.code();
      error_message_ = e.what();
    }
  }

  int run();

 private:
  struct Job {
    mpi::TaskRequest request;
    std::shared_ptr<WorkerScene> scene;
    std::stop_source stop;
    bool running = false;
  };

  void serve_until_stop();
  void executor_loop();
  mpi::TaskReply run_job(const Job& job);
  void keep_scene(mpi::SceneDefinition definition);
  void accept(mpi::TaskRequest request);
  void cancel(std::uint64_t id);
  std::vector<std::byte> cancelled_reply_locked(std::uint64_t id);
  void wait_for_stop();
  void finish();

  const MpiRuntime& runtime_;
  const unsigned threads_;
  BrickCache cache_;
  std::optional<DatasetRegistry> datasets_;
  std::optional<ErrorCode> error_;
  std::string error_message_;
  MpiChannel channel_;  // the MPI thread only

  std::mutex mutex_;  // guards everything below
  std::condition_variable work_;  // executor threads: a job, or stopping
  std::condition_variable wake_;  // the MPI thread: a reply to send
  std::deque<std::shared_ptr<Job>> extracts_, prefetches_;
  std::unordered_map<std::uint64_t, std::shared_ptr<Job>> jobs_;  // queued or running
  std::deque<std::vector<std::byte>> replies_;
  bool stopping_ = false;

  // The scenes rank 0 sent, the MPI thread only: the last mpi::kWorkerScenes of them.
  std::unordered_map<std::uint64_t, std::shared_ptr<WorkerScene>> scenes_;
  std::deque<std::uint64_t> scene_order_;  // oldest first
};

int Worker::run() {
  mpi::WorkerReady ready;
  ready.threads = threads_;
  ready.cache_budget = cache_.stats().budget;
  ready.host = runtime_.host();
  ready.error = error_;
  ready.message = error_message_;
  channel_.send(0, mpi::kReady, mpi::encode(ready));
  if (error_) {
    spdlog::error("MPI rank {} on {}: {}", runtime_.rank(), runtime_.host(), error_message_);
    wait_for_stop();
    finish();
    return exit_status_for(*error_);
  }
  spdlog::debug("MPI rank {} on {}: {} threads, cache {} MiB", runtime_.rank(), runtime_.host(),
                threads_, cache_.stats().budget >> 20);

  std::vector<std::thread> pool;
  for (unsigned i = 0; i < threads_; ++i) pool.emplace_back([this] { executor_loop(); });

  try {
    serve_until_stop();
  } catch (const std::exception& e) {
    // A message rank 0 of this version would never send, or MPI itself failing.
    spdlog::critical("MPI rank {}: {}; aborting every rank", runtime_.rank(), e.what());
    MpiRuntime::abort(1);
  }

  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    for (auto& [id, job] : jobs_) job->stop.request_stop();
    extracts_.clear();
    prefetches_.clear();
    replies_.clear();  // rank 0 no longer waits for them
  }
  work_.notify_all();
  finish();
  for (std::thread& t : pool) t.join();
  const BrickCacheStats c = cache_.stats();
  spdlog::debug("MPI rank {} stopped: cache hits {}, misses {}", runtime_.rank(), c.hits, c.misses);
  return 0;
}

// Sends replies and takes tasks and cancels until rank 0's stop.
void Worker::serve_until_stop() {
  PollBackoff backoff;
  bool stop = false;
  while (!stop) {
    std::deque<std::vector<std::byte>> out;
    {
      std::lock_guard lock(mutex_);
      out.swap(replies_);
    }
    bool active = !out.empty();
    for (auto& bytes : out) channel_.send(0, mpi::kReply, std::move(bytes));
    while (std::optional<MpiChannel::Message> m = channel_.receive()) {
      active = true;
      if (m->tag == mpi::kScene) {
        keep_scene(mpi::decode_scene(m->bytes));
      } else if (m->tag == mpi::kTask) {
        accept(mpi::decode_task(m->bytes));
      } else if (m->tag == mpi::kCancel) {
        cancel(mpi::decode_cancel(m->bytes));
      } else if (m->tag == mpi::kStop) {
        stop = true;  // the last message from rank 0
        break;
      } else {
        spdlog::error("MPI rank {}: unexpected message (tag {}) from rank {}", runtime_.rank(),
                      m->tag, m->source);
      }
    }
    if (stop) break;
    if (active) backoff.reset();
    std::unique_lock lock(mutex_);
    if (replies_.empty()) wake_.wait_for(lock, backoff.next());
  }
}

// Receives until rank 0's stop (for a worker that could not serve).
void Worker::wait_for_stop() {
  PollBackoff backoff;
  for (;;) {
    if (std::optional<MpiChannel::Message> m = channel_.receive()) {
      if (m->tag == mpi::kStop) return;
      backoff.reset();
      continue;
    }
    std::this_thread::sleep_for(backoff.next());
  }
}

// Says kStopped (after everything sent so far) and waits until MPI has delivered it all.
void Worker::finish() {
  channel_.send(0, mpi::kStopped, {});
  PollBackoff backoff;
  while (channel_.progress() > 0) std::this_thread::sleep_for(backoff.next());
}

void Worker::keep_scene(mpi::SceneDefinition definition) {
  const std::uint64_t id = definition.id;
  if (!scenes_.insert_or_assign(id, std::make_shared<WorkerScene>(std::move(definition))).second) {
    return;  // sent again: rank 0 never does, but its place in the order stays
  }
  scene_order_.push_back(id);
  if (scene_order_.size() > mpi::kWorkerScenes) {
    scenes_.erase(scene_order_.front());
    scene_order_.pop_front();
  }
}

void Worker::accept(mpi::TaskRequest request) {
  const auto scene = scenes_.find(request.scene);
  if (scene == scenes_.end()) {
    throw make_error(ErrorCode::kCorrupt, "MPI message Task {}: scene {} was not sent, or was forgotten",
                     request.id, request.scene);
  }
  auto job = std::make_shared<Job>();
  job->request = std::move(request);
  job->scene = scene->second;
  {
    std::lock_guard lock(mutex_);
    jobs_[job->request.id] = job;
    (job->request.kind == mpi::TaskKind::kExtract ? extracts_ : prefetches_).push_back(job);
  }
  work_.notify_one();
}

void Worker::cancel(std::uint64_t id) {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end()) return;  // finished already; its reply is sent or queued
  const std::shared_ptr<Job> job = it->second;
  if (job->running) {
    job->stop.request_stop();  // its reply follows when the task notices
    return;
  }
  std::erase(job->request.kind == mpi::TaskKind::kExtract ? extracts_ : prefetches_, job);
  jobs_.erase(it);
  replies_.push_back(cancelled_reply_locked(id));
  wake_.notify_one();
}

std::vector<std::byte> Worker::cancelled_reply_locked(std::uint64_t id) {
  mpi::TaskReply reply;
  reply.id = id;
  reply.kind = NodeOutputKind::kCancelled;
  reply.cache = cache_.stats();
  return mpi::encode(reply);
}

void Worker::executor_loop() {
  for (;;) {
    std::shared_ptr<Job> job;
    {
      std::unique_lock lock(mutex_);
      work_.wait(lock, [&] { return stopping_ || !extracts_.empty() || !prefetches_.empty(); });
      if (stopping_) return;
      auto& queue = !extracts_.empty() ? extracts_ : prefetches_;
      job = std::move(queue.front());
      queue.pop_front();
      job->running = true;
    }
    std::vector<std::byte> reply = mpi::encode(run_job(*job));
    {
      std::lock_guard lock(mutex_);
      jobs_.erase(job->request.id);
      if (stopping_) return;
      replies_.push_back(std::move(reply));
    }
    wake_.notify_one();
  }
}

mpi::TaskReply Worker::run_job(const Job& job) {
  const mpi::TaskRequest& r = job.request;
  mpi::TaskReply reply;
  reply.id = r.id;
  NodeTask task;
  task.dataset = job.scene->dataset();
  task.generation = r.generation;
  task.node = r.node;
  task.stop = job.stop.get_token();
  try {
    task.store = datasets_->open(task.dataset);
    task.scene = job.scene->resolved(*task.store);
  } catch (const Error& e) {
    // Rank 0 opened the same store and resolved the same scene: the file systems differ.
    if (r.kind == mpi::TaskKind::kExtract) {
      reply.kind = NodeOutputKind::kFailed;
      reply.frame = protocol::encode_frame(protocol::NodeFailed{
          r.generation, r.node, protocol::wire_error(e.code()),
          clipped(fmt::format("MPI rank {} on {}: {}", runtime_.rank(), runtime_.host(),
                              hide_root(e.what(), datasets_->root())))});
    }
    reply.cache = cache_.stats();
    return reply;
  }
  if (r.kind == mpi::TaskKind::kExtract) {
    NodeOutput out = run_node_task(task, cache_);
    reply.kind = out.kind;
    reply.bricks = out.bricks;
    reply.slice_meshes = out.slice_meshes;
    reply.slice_triangles = out.slice_triangles;
    reply.frame = std::move(out.frame);
  } else {
    reply.kind = NodeOutputKind::kEmpty;
    reply.loaded = prefetch_node_task(task, cache_, [this] {
      std::lock_guard lock(mutex_);
      return !extracts_.empty();
    });
  }
  reply.cache = cache_.stats();
  return reply;
}

}  // namespace

int run_mpi_worker(const MpiRuntime& runtime, const MpiWorkerOptions& options) {
  Worker worker(runtime, options);
  return worker.run();
}

}  // namespace strielad::serve
