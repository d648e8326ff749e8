// SPDX-License-Identifier: Apache-2.0
// Server-wide counters behind the Stats message (formats/protocol.md, "Statistics").
#pragma once

#include <atomic>
#include <cstdint>

namespace strielad::serve {

struct ServerCounters {
  std::atomic<std::int64_t> clients{0};      // connections past Welcome
  std::atomic<std::int64_t> handshakes{0};   // connections before Welcome
  std::atomic<std::int64_t> readers_paused{0};  // clients not read: their send queue is full
  std::atomic<std::int64_t> send_queue_bytes{0};  // frames waiting for every client
  std::atomic<std::uint64_t> send_queue_peak_bytes{0};  // most one client's queue held
  std::atomic<std::uint64_t> handshakes_dropped{0};  // timed out or pushed out by newer ones
  std::atomic<std::int64_t> queued{0};   // nodes waiting in every client's queue
  std::atomic<std::int64_t> running{0};  // nodes being extracted
  std::atomic<std::uint64_t> nodes_done{0};       // results sent (mesh or empty)
  std::atomic<std::uint64_t> nodes_skipped{0};    // sent as skipped without reading data
  std::atomic<std::uint64_t> nodes_failed{0};     // NodeFailed sent
  std::atomic<std::uint64_t> nodes_cancelled{0};  // dropped: obsolete, removed or aborted
  std::atomic<std::uint64_t> bytes_sent{0};
  std::atomic<std::uint64_t> slice_meshes{0};     // slice meshes in results sent
  std::atomic<std::uint64_t> slice_triangles{0};  // their triangles
  std::atomic<std::uint64_t> prefetch_nodes{0};
  std::atomic<std::uint64_t> prefetch_bricks{0};
  std::atomic<std::uint64_t> connections_rejected{0};  // busy, bad token, bad handshake
};

}  // namespace strielad::serve
