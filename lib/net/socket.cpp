// SPDX-License-Identifier: Apache-2.0
#include "net/socket.h"

#include <arpa/inet.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstring>

#include "core/error.h"

namespace strielad::net {

namespace {

std::string system_reason(int err) { return std::strerror(err); }

std::string address_text(const sockaddr_storage& addr) {
  char host[NI_MAXHOST] = "?";
  char port[NI_MAXSERV] = "?";
  getnameinfo(reinterpret_cast<const sockaddr*>(&addr), sizeof addr, host, sizeof host, port,
              sizeof port, NI_NUMERICHOST | NI_NUMERICSERV);
  const bool v6 = addr.ss_family == AF_INET6;
  return fmt::format("{}{}{}:{}", v6 ? "[" : "", host, v6 ? "]" : "", port);
}

struct AddrInfoList {
  addrinfo* head = nullptr;
  ~AddrInfoList() {
    if (head) freeaddrinfo(head);
  }
};

AddrInfoList resolve(const Endpoint& endpoint, bool passive) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_NUMERICSERV | (passive ? AI_PASSIVE : 0);
  AddrInfoList list;
  const std::string port = std::to_string(endpoint.port);
  const int rc = getaddrinfo(endpoint.host.c_str(), port.c_str(), &hints, &list.head);
  if (rc != 0) {
    throw make_error(ErrorCode::kIo, "{}: cannot resolve host: {}", endpoint.to_string(),
                     gai_strerror(rc));
  }
  return list;
}

}  // namespace

std::string Endpoint::to_string() const {
  const bool v6 = host.find(':') != std::string::npos;
  return fmt::format("{}{}{}:{}", v6 ? "[" : "", host, v6 ? "]" : "", port);
}

Endpoint parse_endpoint(std::string_view text, std::string_view what) {
  const std::size_t colon = text.rfind(':');
  if (colon == std::string_view::npos) {
    throw make_error(ErrorCode::kInvalidArgument, "{}: '{}' is not HOST:PORT", what, text);
  }
  std::string_view host = text.substr(0, colon);
  const std::string_view port_text = text.substr(colon + 1);
  if (host.size() >= 2 && host.front() == '[' && host.back() == ']') {
    host = host.substr(1, host.size() - 2);
  }
  unsigned port = 0;
  const auto [end, ec] = std::from_chars(port_text.data(), port_text.data() + port_text.size(), port);
  if (ec != std::errc{} || end != port_text.data() + port_text.size() || port > 65535) {
    throw make_error(ErrorCode::kInvalidArgument, "{}: '{}' has no valid port (0..65535)", what,
                     text);
  }
  Endpoint e;
  if (!host.empty()) e.host = std::string(host);
  e.port = static_cast<std::uint16_t>(port);
  return e;
}

Socket::Socket(Socket&& other) noexcept : fd_(other.fd_), peer_(std::move(other.peer_)) {
  other.fd_ = -1;
}

Socket& Socket::operator=(Socket&& other) noexcept {
  if (this != &other) {
    close();
    fd_ = other.fd_;
    peer_ = std::move(other.peer_);
    other.fd_ = -1;
  }
  return *this;
}

Socket::~Socket() { close(); }

void Socket::shutdown() const noexcept {
  if (fd_ >= 0) ::shutdown(fd_, SHUT_RDWR);
}

void Socket::close() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

void Socket::set_receive_timeout(std::chrono::milliseconds timeout) const {
  timeval tv{};
  tv.tv_sec = static_cast<time_t>(timeout.count() / 1000);
  tv.tv_usec = static_cast<suseconds_t>((timeout.count() % 1000) * 1000);
  setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
}

void Socket::wait_readable_before(Deadline deadline) const {
  for (;;) {
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) throw make_error(ErrorCode::kIo, "{}: read deadline passed", peer_);
    pollfd p{fd_, POLLIN, 0};
    const int rc = ::poll(&p, 1, static_cast<int>(std::min<std::int64_t>(left.count(), 1 << 30)));
    if (rc > 0) return;  // data, end of stream or an error: recv tells which
    if (rc < 0 && errno != EINTR) {
      throw make_error(ErrorCode::kIo, "{}: poll failed: {}", peer_, system_reason(errno));
    }
  }
}

void Socket::write_all(std::span<const std::byte> bytes) const {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::send(fd_, bytes.data() + done, bytes.size() - done, MSG_NOSIGNAL);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw make_error(ErrorCode::kIo, "{}: write failed: {}", peer_, system_reason(errno));
    }
    done += static_cast<std::size_t>(n);
  }
}

bool Socket::read_exact(std::span<std::byte> bytes) const { return read_exact_until(bytes, nullptr); }

bool Socket::read_exact(std::span<std::byte> bytes, Deadline deadline) const {
  return read_exact_until(bytes, &deadline);
}

bool Socket::read_exact_until(std::span<std::byte> bytes, const Deadline* deadline) const {
  std::size_t done = 0;
  while (done < bytes.size()) {
    if (deadline) wait_readable_before(*deadline);
    const ssize_t n = ::recv(fd_, bytes.data() + done, bytes.size() - done, 0);
    if (n < 0) {
      if (errno == EINTR) continue;
      if (errno == EAGAIN || errno == EWOULDBLOCK) {
        throw make_error(ErrorCode::kIo, "{}: read timed out", peer_);
      }
      throw make_error(ErrorCode::kIo, "{}: read failed: {}", peer_, system_reason(errno));
    }
    if (n == 0) {
      if (done == 0) return false;
      throw make_error(ErrorCode::kIo, "{}: connection closed after {} of {} bytes", peer_, done,
                       bytes.size());
    }
    done += static_cast<std::size_t>(n);
  }
  return true;
}

namespace {

// Tries each address the endpoint resolves to: a socket, then `use` (bind+listen or
// connect); the first that works is returned. \error kIo with the last reason.
template <typename Use>
Socket first_working_socket(const Endpoint& endpoint, bool passive, std::string_view what,
                            Use use) {
  const AddrInfoList list = resolve(endpoint, passive);
  int last_error = 0;
  for (addrinfo* ai = list.head; ai; ai = ai->ai_next) {
    Socket s(::socket(ai->ai_family, ai->ai_socktype | SOCK_CLOEXEC, ai->ai_protocol),
             endpoint.to_string());
    if (s.is_open() && use(s, *ai)) return s;
    last_error = errno;
  }
  throw make_error(ErrorCode::kIo, "{}: cannot {}: {}", endpoint.to_string(), what,
                   system_reason(last_error));
}

void set_int_option(const Socket& s, int level, int option) {
  const int one = 1;
  setsockopt(s.fd(), level, option, &one, sizeof one);
}

}  // namespace

Socket listen_tcp(const Endpoint& endpoint, int backlog) {
  return first_working_socket(endpoint, true, "listen", [&](const Socket& s, const addrinfo& ai) {
    set_int_option(s, SOL_SOCKET, SO_REUSEADDR);
    return ::bind(s.fd(), ai.ai_addr, ai.ai_addrlen) == 0 && ::listen(s.fd(), backlog) == 0;
  });
}

std::uint16_t local_port(const Socket& socket) {
  sockaddr_storage addr{};
  socklen_t len = sizeof addr;
  if (getsockname(socket.fd(), reinterpret_cast<sockaddr*>(&addr), &len) != 0) {
    throw make_error(ErrorCode::kIo, "getsockname failed: {}", system_reason(errno));
  }
  if (addr.ss_family == AF_INET6) return ntohs(reinterpret_cast<sockaddr_in6&>(addr).sin6_port);
  return ntohs(reinterpret_cast<sockaddr_in&>(addr).sin_port);
}

std::optional<Socket> accept_for(const Socket& listener, std::chrono::milliseconds timeout) {
  pollfd p{listener.fd(), POLLIN, 0};
  const int rc = ::poll(&p, 1, static_cast<int>(timeout.count()));
  if (rc < 0) {
    if (errno == EINTR) return std::nullopt;
    throw make_error(ErrorCode::kIo, "poll on listener failed: {}", system_reason(errno));
  }
  if (rc == 0 || !(p.revents & POLLIN)) return std::nullopt;
  sockaddr_storage addr{};
  socklen_t len = sizeof addr;
  const int fd = ::accept4(listener.fd(), reinterpret_cast<sockaddr*>(&addr), &len, SOCK_CLOEXEC);
  if (fd < 0) {
    if (errno == EINTR || errno == EAGAIN || errno == ECONNABORTED || errno == EINVAL) {
      return std::nullopt;
    }
    throw make_error(ErrorCode::kIo, "accept failed: {}", system_reason(errno));
  }
  Socket client(fd, address_text(addr));
  set_int_option(client, IPPROTO_TCP, TCP_NODELAY);
  return client;
}

Socket connect_tcp(const Endpoint& endpoint) {
  return first_working_socket(endpoint, false, "connect", [](const Socket& s, const addrinfo& ai) {
    if (::connect(s.fd(), ai.ai_addr, ai.ai_addrlen) != 0) return false;
    set_int_option(s, IPPROTO_TCP, TCP_NODELAY);
    return true;
  });
}

}  // namespace strielad::net
