// SPDX-License-Identifier: Apache-2.0
#include "serve/server.h"

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include <thread>

#include "core/error.h"
#include "net/message_stream.h"
#include "serve/session.h"

namespace strielad::serve {

namespace {

unsigned worker_count(unsigned requested) {
  return requested ? requested : std::max(1u, std::thread::hardware_concurrency());
}

std::unique_ptr<NodeExecutor> or_local(std::unique_ptr<NodeExecutor> executor,
                                       std::uint64_t cache_bytes) {
  if (executor) return executor;
  return std::make_unique<LocalNodeExecutor>(cache_bytes);
}

}  // namespace

Server::Server(ServerConfig config, std::unique_ptr<NodeExecutor> executor)
    : config_(std::move(config)),
      executor_(or_local(std::move(executor), config_.cache_bytes)),
      datasets_(config_.root, config_.direct_reads),
      dispatcher_(worker_count(config_.threads), *executor_, counters_, config_.prefetch),
      listener_(net::listen_tcp(config_.listen)),
      port_(net::local_port(listener_)) {
  spdlog::info("serving stores under {} on {}:{} ({} workers, cache {} MiB, prefetch {}, token {})",
               datasets_.root().string(), config_.listen.host, port_, dispatcher_.workers(),
               config_.cache_bytes >> 20, config_.prefetch ? "on" : "off",
               config_.token ? "required" : "none");
}

Server::~Server() {
  stop();
  wait();
}

void Server::start() {
  background_ = std::thread([this] { run(); });
}

void Server::stop() {
  if (stopping_.exchange(true)) return;
  spdlog::info("server stopping");
  listener_.shutdown();
  std::lock_guard lock(connections_mutex_);
  for (Connection& c : connections_) c.session->shutdown();
}

void Server::wait() {
  if (background_.joinable() && background_.get_id() != std::this_thread::get_id()) {
    background_.join();
  }
}

void Server::run() {
  while (!stopping_) {
    std::optional<net::Socket> client;
    try {
      client = net::accept_for(listener_, std::chrono::milliseconds(200));
    } catch (const Error& e) {
      spdlog::warn("{}", e.what());
    }
    reap_finished();
    if (client) accept_client(std::move(*client));
  }
  std::list<Connection> remaining;
  {
    std::lock_guard lock(connections_mutex_);
    for (Connection& c : connections_) c.session->shutdown();
    remaining.splice(remaining.end(), connections_);
  }
  for (Connection& c : remaining) {
    c.thread.join();
    dispatcher_.detach(c.session.get());
  }
  listener_.close();
}

void Server::accept_client(net::Socket socket) {
  std::lock_guard lock(connections_mutex_);
  make_room_for_handshake_locked();
  SessionContext context{config_, datasets_, counters_, [this] { dispatcher_.notify(); },
                         [this](std::uint32_t generation) { return stats_json(generation); },
                         [this] { return admit_client(); }};
  auto session = std::make_shared<Session>(next_session_id_++, std::move(socket), std::move(context));
  dispatcher_.attach(session);
  Connection& c = connections_.emplace_back();
  c.session = session;
  ++counters_.handshakes;  // the session leaves this count when its handshake ends
  c.thread = std::thread([this, session, &c] {
    session->run();
    dispatcher_.detach(session.get());
    if (session->admitted()) --counters_.clients;
    c.finished = true;
  });
  if (stopping_) session->shutdown();
}

void Server::make_room_for_handshake_locked() {
  std::size_t waiting = 0;
  Connection* oldest = nullptr;
  for (Connection& c : connections_) {
    if (c.pushed_out || !c.session->in_handshake()) continue;
    if (!oldest) oldest = &c;
    ++waiting;
  }
  if (waiting < std::max<std::size_t>(config_.max_handshakes, 1) || !oldest) return;
  // The oldest has had the longest to say Hello; a client that answers at once is
  // never pushed out unless max_handshakes connections arrive within its round trip.
  oldest->pushed_out = true;
  ++counters_.handshakes_dropped;
  spdlog::info("client {} ({}): {} connections in their handshake (limit {}); closing the oldest",
               oldest->session->id(), oldest->session->peer(), waiting, config_.max_handshakes);
  oldest->session->shutdown();
}

bool Server::admit_client() {
  std::int64_t now = counters_.clients.load();
  while (now < static_cast<std::int64_t>(config_.max_clients)) {
    if (counters_.clients.compare_exchange_weak(now, now + 1)) return true;
  }
  return false;  // the session refuses the client (and counts it in connections_rejected)
}

void Server::reap_finished() {
  std::lock_guard lock(connections_mutex_);
  for (auto it = connections_.begin(); it != connections_.end();) {
    if (it->finished) {
      it->thread.join();
      it = connections_.erase(it);
    } else {
      ++it;
    }
  }
}

std::string Server::stats_json(std::uint32_t generation) const {
  const BrickCacheStats cache = executor_->cache_stats();
  nlohmann::json j = {
      {"clients", counters_.clients.load()},
      {"max_clients", config_.max_clients},
      {"handshakes", counters_.handshakes.load()},
      {"max_handshakes", config_.max_handshakes},
      {"handshakes_dropped", counters_.handshakes_dropped.load()},
      {"readers_paused", counters_.readers_paused.load()},
      {"send_queue_bytes", counters_.send_queue_bytes.load()},
      {"send_queue_peak_bytes", counters_.send_queue_peak_bytes.load()},
      {"max_send_queue_bytes", config_.max_pending_send_bytes},
      {"generation", generation},
      {"queued", counters_.queued.load()},
      {"running", counters_.running.load()},
      {"nodes_done", counters_.nodes_done.load()},
      {"nodes_skipped", counters_.nodes_skipped.load()},
      {"nodes_failed", counters_.nodes_failed.load()},
      {"nodes_cancelled", counters_.nodes_cancelled.load()},
      {"bytes_sent", counters_.bytes_sent.load()},
      {"slice_meshes", counters_.slice_meshes.load()},
      {"slice_triangles", counters_.slice_triangles.load()},
      {"connections_rejected", counters_.connections_rejected.load()},
      {"cache",
       {{"hits", cache.hits},
        {"misses", cache.misses},
        {"evictions", cache.evictions},
        {"bytes", cache.bytes},
        {"budget", cache.budget},
        {"entries", cache.entries},
        {"hit_rate", cache.hit_rate()}}},
      {"prefetch", {{"nodes", counters_.prefetch_nodes.load()}, {"bricks", counters_.prefetch_bricks.load()}}},
      {"ranks", executor_->ranks()},
      {"workers", dispatcher_.workers()},
  };
  return j.dump();
}

}  // namespace strielad::serve
