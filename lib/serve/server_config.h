// SPDX-License-Identifier: Apache-2.0
// Everything strielad-serve can be told (docs/serve.md; formats/protocol.md).
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "net/socket.h"
#include "protocol/messages.h"

namespace strielad::serve {

inline constexpr std::uint16_t kDefaultPort = 7420;

struct ServerConfig {
  // Datasets are stores under this folder, opened by their relative name.
  std::filesystem::path root;
  net::Endpoint listen{"127.0.0.1", kDefaultPort};
  // Shared secret every Hello must carry; none when empty.
  std::optional<std::string> token;
  unsigned threads = 0;  // extraction workers; 0 = one per hardware thread
  std::uint64_t cache_bytes = 1ull << 30;
  // Read bricks with O_DIRECT, past the page cache (StoreOpenOptions::direct_reads).
  bool direct_reads = false;
  // Connections that have received Welcome; one more that authenticates is refused
  // with ServerBusy.
  std::size_t max_clients = 64;
  // Connections still in the handshake (before Welcome), counted apart from max_clients
  // so that they never take an authenticated client's slot. When this many are waiting,
  // a new connection pushes out the one that has waited longest.
  std::size_t max_handshakes = 64;
  bool prefetch = true;
  std::string server_name = "strielad-serve";
  // Limits announced in Welcome and enforced on every client message.
  protocol::ServerLimits limits;
  // Encoded frames (results and every other reply) waiting to be sent to one client.
  // Above this the client's extraction pauses and the server stops reading its requests
  // until it reads (back-pressure: a slow reader cannot make the server hold unbounded
  // memory). One reply or one result per worker may go over it.
  std::uint64_t max_pending_send_bytes = 64ull << 20;
  // The whole handshake, from accept to Welcome, however the Hello's bytes trickle in.
  std::chrono::milliseconds handshake_timeout{10000};
};

}  // namespace strielad::serve
