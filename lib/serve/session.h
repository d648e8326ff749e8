// SPDX-License-Identifier: Apache-2.0
// One client connection of strielad-serve (formats/protocol.md, "Session"): the
// handshake, the open dataset, the scene and time step of the current generation, the
// client's cut and the queue of its pending nodes. The connection's thread reads and
// handles messages (run()); a writer thread sends frames in order; the dispatcher's
// workers take tasks from it and hand results back. A result is sent only when its
// generation is still current and its node is still in the cut, checked under the same
// lock that starts generations, so no stale result can ever reach the client.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "net/socket.h"
#include "protocol/messages.h"
#include "scene/scene.h"
#include "serve/node_executor.h"
#include "serve/send_queue.h"
#include "serve/server_config.h"
#include "serve/server_counters.h"
#include "serve/work_queue.h"

namespace strielad::serve {

class DatasetRegistry;

struct SessionContext {
  const ServerConfig& config;
  DatasetRegistry& datasets;
  ServerCounters& counters;
  std::function<void()> work_available;               // wakes the dispatcher
  std::function<std::string(std::uint32_t)> stats_json;  // argument: the session's generation
  // Takes one of the max_clients slots for a client that passed the handshake; false
  // when every slot is taken (the client is refused with ServerBusy).
  std::function<bool()> admit_client;
};

class Session {
 public:
  Session(std::uint64_t id, net::Socket socket, SessionContext context);
  ~Session();

  std::uint64_t id() const { return id_; }
  const std::string& peer() const { return socket_.peer(); }

  // Runs the connection until the client leaves, breaks the protocol or shutdown() is
  // called; cancels all its work before returning. Call once, on the session's thread.
  void run();
  // Makes run() return soon (from any thread).
  void shutdown();
  // Before Welcome (or the handshake's failure). The server counts such connections in
  // ServerCounters::handshakes and the session leaves that count when it ends.
  bool in_handshake() const { return in_handshake_; }
  // The handshake took a client slot (admit_client), to be given back when run() returns.
  bool admitted() const { return admitted_; }

  // For the dispatcher. take_task pops the client's most urgent node (none while the
  // client has more than ServerConfig::max_pending_send_bytes unsent).
  std::optional<NodeTask> take_task();
  void complete(const NodeTask& task, NodeOutput output);
  // The next node of the cut whose bricks of the next time step are not yet warmed;
  // only when the client has nothing queued or running.
  std::optional<NodeTask> take_prefetch();
  bool has_queued_work() const;

 private:
  bool handshake();
  void leave_handshake();
  // Back-pressure: returns once the client's send queue is within max_pending_send_bytes,
  // so that its requests are not read (and answered) faster than it reads the answers.
  void wait_for_send_room();
  // Returns false when the connection must end.
  bool handle(const protocol::Message& message);
  void open_dataset(const protocol::OpenDataset& m);
  void set_scene(const protocol::SetScene& m);
  void set_time(const protocol::SetTime& m);
  void update_cut(const protocol::CutUpdate& m);
  void start_generation(std::uint32_t generation, Scene scene, ResolvedScene resolved);
  bool check_new_generation(std::uint32_t generation);  // sends the error when not
  void cancel_all_locked();
  // Queued work, and the client reads its results (not over max_pending_send_bytes).
  bool can_take_work_locked() const;
  void send(const protocol::Message& message);
  void send_error(protocol::WireError code, std::string message, bool fatal = false);
  void writer_loop();

  const std::uint64_t id_;
  net::Socket socket_;
  // The protocol version agreed in Welcome (set by the handshake, before the reader
  // loop; read-only afterwards).
  std::uint16_t version_ = 1;
  std::atomic<bool> in_handshake_{true};
  std::atomic<bool> admitted_{false};
  SessionContext context_;
  SendQueue outbound_;

  mutable std::mutex mutex_;  // guards everything below
  bool closed_ = false;
  std::string dataset_;
  std::shared_ptr<const Store> store_;
  std::optional<Scene> scene_;
  std::shared_ptr<const ResolvedScene> resolved_;       // scene at step
  std::shared_ptr<const ResolvedScene> resolved_next_;  // scene at step + 1 (prefetch)
  std::shared_ptr<const SceneSource> source_;       // resolved_ as the client's JSON
  std::shared_ptr<const SceneSource> source_next_;  // resolved_next_ likewise
  std::uint32_t generation_ = 0;  // the last accepted; 0 before the first
  bool generation_started_ = false;  // a generation is current (OpenDataset ends it)
  std::unordered_map<NodeId, float> cut_;  // the client's cut in this generation
  WorkQueue queue_;
  struct Running {
    std::uint64_t serial;
    std::stop_source stop;
  };
  std::unordered_map<NodeId, Running> running_;
  std::uint64_t next_serial_ = 1;
  std::stop_source generation_stop_;  // stops prefetching of the generation
  std::vector<NodeId> prefetch_order_;
  std::size_t prefetch_cursor_ = 0;
  bool prefetch_order_stale_ = true;
  std::unordered_set<NodeId> prefetched_;
};

}  // namespace strielad::serve
