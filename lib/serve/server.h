// SPDX-License-Identifier: Apache-2.0
// strielad-serve's threaded server: accepts clients on a TCP endpoint, runs one
// Session per connection on its own thread, and extracts their nodes on a shared
// Dispatcher through one NodeExecutor (an in-process brick cache, or MPI worker ranks).
#pragma once

#include <atomic>
#include <cstdint>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "net/socket.h"
#include "serve/dataset_registry.h"
#include "serve/dispatcher.h"
#include "serve/node_executor.h"
#include "serve/server_config.h"
#include "serve/server_counters.h"

namespace strielad::serve {

class Session;

class Server {
 public:
  // Binds the listening socket; with no executor, extracts in-process with a cache of
  // config.cache_bytes. \error kNotFound when the root is missing, kIo when the
  // endpoint cannot be bound.
  explicit Server(ServerConfig config, std::unique_ptr<NodeExecutor> executor = nullptr);
  ~Server();  // stop() and wait()

  std::uint16_t port() const { return port_; }
  const ServerConfig& config() const { return config_; }

  // Accepts clients until stop(); returns after every session has ended.
  void run();
  // run() on a background thread.
  void start();
  // Thread-safe and idempotent (a signal-watching thread may call it).
  void stop();
  void wait();

  std::string stats_json(std::uint32_t generation = 0) const;
  const ServerCounters& counters() const { return counters_; }

 private:
  struct Connection {
    std::shared_ptr<Session> session;
    std::thread thread;
    std::atomic<bool> finished{false};
    bool pushed_out = false;  // closed in its handshake to make room for a newer one
  };
  void accept_client(net::Socket socket);
  // With max_handshakes connections in their handshake, closes the one accepted first.
  void make_room_for_handshake_locked();
  // Takes a max_clients slot for a session past its handshake; false when none is free.
  bool admit_client();
  void reap_finished();

  ServerConfig config_;
  std::unique_ptr<NodeExecutor> executor_;
  ServerCounters counters_;
  DatasetRegistry datasets_;
  Dispatcher dispatcher_;
  net::Socket listener_;
  std::uint16_t port_ = 0;
  std::atomic<bool> stopping_{false};
  std::uint64_t next_session_id_ = 1;
  std::mutex connections_mutex_;
  std::list<Connection> connections_;
  std::thread background_;
};

}  // namespace strielad::serve
