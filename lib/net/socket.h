// SPDX-License-Identifier: Apache-2.0
// Blocking TCP sockets over POSIX, as the protocol (formats/protocol.md) needs them:
// listen, accept with a timeout, connect, write everything, read exactly n bytes.
// Failures throw strielad::Error kIo naming the peer and the system's reason.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace strielad::net {

struct Endpoint {
  std::string host = "127.0.0.1";
  std::uint16_t port = 0;
  std::string to_string() const;
};

// "HOST:PORT", "[V6ADDR]:PORT" or ":PORT" (host 127.0.0.1).
// \error kInvalidArgument naming `what` for anything else.
Endpoint parse_endpoint(std::string_view text, std::string_view what);

using Deadline = std::chrono::steady_clock::time_point;

// A move-only owned socket descriptor.
class Socket {
 public:
  Socket() = default;
  explicit Socket(int fd, std::string peer = {}) : fd_(fd), peer_(std::move(peer)) {}
  Socket(Socket&& other) noexcept;
  Socket& operator=(Socket&& other) noexcept;
  Socket(const Socket&) = delete;
  Socket& operator=(const Socket&) = delete;
  ~Socket();

  int fd() const { return fd_; }
  bool is_open() const { return fd_ >= 0; }
  const std::string& peer() const { return peer_; }  // "127.0.0.1:53122", for messages
  // Ends both directions so that a thread blocked in read or write returns; the
  // descriptor stays owned until close() or destruction. Safe from any thread.
  void shutdown() const noexcept;
  void close() noexcept;
  // A read that waits longer than this fails with kIo (0: wait forever).
  void set_receive_timeout(std::chrono::milliseconds timeout) const;

  // Writes all bytes (no SIGPIPE). \error kIo when the peer is gone.
  void write_all(std::span<const std::byte> bytes) const;
  // Reads exactly bytes.size() bytes. Returns false when the peer closed the connection
  // before the first byte; \error kIo when it closes in the middle or the read fails.
  bool read_exact(std::span<std::byte> bytes) const;
  // The same, and \error kIo when `deadline` passes before the last byte arrived
  // (however slowly the bytes trickle in).
  bool read_exact(std::span<std::byte> bytes, Deadline deadline) const;

 private:
  bool read_exact_until(std::span<std::byte> bytes, const Deadline* deadline) const;
  // Returns once the socket is readable. \error kIo when the deadline passes first.
  void wait_readable_before(Deadline deadline) const;

  int fd_ = -1;
  std::string peer_;
};

// Listens on the endpoint (port 0: the system picks one; see local_port).
// \error kIo when the address cannot be resolved or bound.
Socket listen_tcp(const Endpoint& endpoint, int backlog = 64);
std::uint16_t local_port(const Socket& socket);

// Waits up to `timeout` for a connection. nullopt on timeout or when the listener was
// shut down. \error kIo on other failures.
std::optional<Socket> accept_for(const Socket& listener, std::chrono::milliseconds timeout);

// Connects with TCP_NODELAY set. \error kIo naming the endpoint when it cannot.
Socket connect_tcp(const Endpoint& endpoint);

}  // namespace strielad::net
