// SPDX-License-Identifier: Apache-2.0
#include "bench/soak_clients.h"

#include <poll.h>
#include <spdlog/spdlog.h>
#include <sys/socket.h>

#include <cerrno>
#include <thread>
#include <vector>

#include "client/server_client.h"
#include "core/error.h"
#include "net/message_stream.h"
#include "protocol/message_codec.h"
#include "scene/scene.h"

namespace strielad::bench {

namespace {

using namespace std::chrono_literals;

// Two scenes, so that consecutive rounds of a client extract different surfaces.
constexpr const char* kScenes[] = {
    R"({"subvolumes": [{"id": 1, "limits": [{"var": "clw", "min": 1e-5}]},
                       {"id": 2, "limits": [{"var": "cli", "min": 1e-6}]}],
        "attributes": ["ta"]})",
    R"({"subvolumes": [{"id": 1, "limits": [{"var": "clw", "min": 1e-4}]}],
        "attributes": ["ta"]})"};

bool is_busy(const Error& e) { return std::string_view(e.what()).find("busy") != std::string_view::npos; }

// Sleeps up to `d` in short steps; false once `end` has passed.
bool nap(std::chrono::milliseconds d, SoakClock::time_point end) {
  const auto until = std::min(end, SoakClock::now() + d);
  while (SoakClock::now() < until) std::this_thread::sleep_for(std::min<SoakClock::duration>(50ms, until - SoakClock::now()));
  return SoakClock::now() < end;
}

// True when the peer closed the connection (end of stream or reset); never blocks.
bool closed_by_peer(const net::Socket& s) {
  pollfd p{s.fd(), POLLIN, 0};
  if (::poll(&p, 1, 0) <= 0) return false;
  std::byte b{};
  const ssize_t n = ::recv(s.fd(), &b, 1, MSG_DONTWAIT | MSG_PEEK);
  return n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK);
}

std::vector<protocol::NodePriority> whole_cut(std::size_t nodes) {
  std::vector<protocol::NodePriority> cut;
  cut.reserve(nodes);
  for (std::size_t n = 0; n < nodes; ++n) cut.push_back({static_cast<NodeId>(n), float(nodes - n)});
  return cut;
}

// One round of a normal client; false when it did not end with the whole cut answered.
bool normal_round(const SoakTarget& target, int index, std::uint64_t round, SoakTally& tally) {
  client::ClientOptions options;
  options.client_name = fmt::format("soak client {}", index);
  options.timeout = target.timeout;
  auto c = client::ServerClient::connect(target.endpoint, options);
  ++tally.connections;
  c->open_dataset(target.dataset);
  const auto started = c->set_scene(parse_scene(kScenes[(index + round) % 2], "soak scene"));
  const std::size_t nodes = c->octree().node_count();
  c->update_cut(whole_cut(nodes), {}, {});
  std::size_t answered = 0;
  while (answered < nodes) {
    const auto m = c->wait(target.timeout);
    if (!m) {
      spdlog::warn("bench: soak client {}: {} of {} nodes answered within {} ms", index, answered,
                   nodes, target.timeout.count());
      return false;
    }
    if (const auto* r = std::get_if<protocol::NodeResult>(&*m); r && r->generation == started.generation) {
      ++answered;
    } else if (const auto* f = std::get_if<protocol::NodeFailed>(&*m)) {
      spdlog::warn("bench: soak client {}: node {} failed: {}", index, f->node, f->message);
      return false;
    } else if (const auto* e = std::get_if<protocol::ErrorMessage>(&*m)) {
      spdlog::warn("bench: soak client {}: {}", index, e->message);
      return false;
    }
  }
  tally.answers += answered;
  c->stats(target.timeout);
  return true;
}

}  // namespace

void run_normal_client(const SoakTarget& target, int index, SoakClock::time_point end,
                       SoakTally& tally) {
  for (std::uint64_t round = 0; SoakClock::now() < end; ++round) {
    try {
      if (normal_round(target, index, round, tally)) {
        ++tally.rounds;
      } else {
        ++tally.errors;
      }
    } catch (const Error& e) {
      if (is_busy(e)) {
        ++tally.refused;
      } else {
        ++tally.errors;
        spdlog::warn("bench: soak client {}: {}", index, e.what());
      }
      nap(200ms, end);
    }
  }
}

void run_slow_reader(const SoakTarget& target, int index, SoakClock::time_point end,
                     SoakTally& tally) {
  while (SoakClock::now() < end) {
    net::Socket s;
    try {
      s = net::connect_tcp(target.endpoint);
      ++tally.connections;
      net::write_message(s, protocol::Hello{protocol::kProtocolVersion,
                                            fmt::format("soak slow reader {}", index), ""});
      const auto welcome = net::read_message(s, protocol::kMaxServerPayloadBytes,
                                             SoakClock::now() + target.timeout);
      if (!std::holds_alternative<protocol::Welcome>(welcome.message)) {
        const auto* e = std::get_if<protocol::ErrorMessage>(&welcome.message);
        if (e && e->code == protocol::WireError::kServerBusy) {
          ++tally.refused;
        } else {
          ++tally.errors;
        }
        nap(1s, end);
        continue;
      }
    } catch (const Error& e) {
      ++tally.errors;
      spdlog::warn("bench: soak slow reader {}: {}", index, e.what());
      nap(1s, end);
      continue;
    }
    // Requests without end, written whenever the server reads; answers never read.
    std::uint32_t generation = 0;
    std::vector<std::byte> pending;
    std::size_t written = 0;
    bool open = true;
    while (open && SoakClock::now() < end) {
      if (written == pending.size()) {
        ++generation;
        pending.clear();
        written = 0;
        for (const protocol::Message& m :
             {protocol::Message(protocol::OpenDataset{target.dataset}),
              protocol::Message(protocol::SetScene{generation, kScenes[generation % 2]}),
              protocol::Message(protocol::CutUpdate{generation, whole_cut(target.octree_nodes), {}, {}}),
              protocol::Message(protocol::StatsRequest{})}) {
          const auto frame = protocol::encode_frame(m);
          pending.insert(pending.end(), frame.begin(), frame.end());
        }
        tally.requests += 4;
      }
      const ssize_t n = ::send(s.fd(), pending.data() + written, pending.size() - written,
                               MSG_DONTWAIT | MSG_NOSIGNAL);
      if (n > 0) {
        written += static_cast<std::size_t>(n);
      } else if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK || errno == EINTR)) {
        nap(200ms, end);  // the server stopped reading: wait
      } else {
        open = false;
      }
    }
    if (!open) {
      ++tally.closed_by_server;
      nap(1s, end);
    }
  }
}

void run_trickler(const SoakTarget& target, std::chrono::milliseconds interval,
                  SoakClock::time_point end, SoakTally& tally) {
  const std::vector<std::byte> hello = protocol::encode_frame(
      protocol::Hello{protocol::kProtocolVersion, "soak trickler", "never finished"});
  while (SoakClock::now() < end) {
    net::Socket s;
    try {
      s = net::connect_tcp(target.endpoint);
    } catch (const Error&) {
      ++tally.errors;
      nap(1s, end);
      continue;
    }
    ++tally.connections;
    bool closed = false;
    for (std::size_t i = 0; i + 1 < hello.size() && !closed; ++i) {
      try {
        s.write_all(std::span(hello).subspan(i, 1));
      } catch (const Error&) {
        closed = true;
        break;
      }
      // Wait for the next byte's turn, noticing a close meanwhile.
      const auto next = SoakClock::now() + interval;
      while (!closed && SoakClock::now() < next) {
        if (!nap(100ms, end)) return;
        closed = closed_by_peer(s);
      }
    }
    if (closed) ++tally.closed_by_server;
    nap(1s, end);
  }
}

}  // namespace strielad::bench
