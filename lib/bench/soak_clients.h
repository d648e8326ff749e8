// SPDX-License-Identifier: Apache-2.0
// The clients of the soak suite (bench/soak_suite.h), each a loop on its own thread until
// `end`:
//  - a normal client connects, opens the dataset, sets a scene, asks for the whole octree,
//    waits for every answer, asks for Stats, says Goodbye, and starts over;
//  - a slow reader connects once and sends OpenDataset, SetScene, CutUpdate and
//    StatsRequest for ever without reading an answer (it writes while the server reads);
//  - a trickler connects and sends a Hello one byte every interval, never finishing it,
//    and connects again a second after the server closes it.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>

#include "net/socket.h"

namespace strielad::bench {

using SoakClock = std::chrono::steady_clock;

// What the clients of one kind did; updated while they run.
struct SoakTally {
  std::atomic<std::uint64_t> connections{0};  // connections opened
  std::atomic<std::uint64_t> rounds{0};       // normal: whole cuts answered
  std::atomic<std::uint64_t> answers{0};      // normal: NodeResult and NodeFailed received
  std::atomic<std::uint64_t> requests{0};     // slow readers: requests written
  std::atomic<std::uint64_t> refused{0};      // refused with ServerBusy
  std::atomic<std::uint64_t> errors{0};       // any other error, timeout or lost connection
  std::atomic<std::uint64_t> closed_by_server{0};  // tricklers, slow readers: the server closed
};

struct SoakTarget {
  net::Endpoint endpoint;
  std::string dataset;
  std::size_t octree_nodes = 0;
  std::chrono::milliseconds timeout{20000};  // a whole cut's answers, a reply
};

void run_normal_client(const SoakTarget& target, int index, SoakClock::time_point end,
                       SoakTally& tally);
void run_slow_reader(const SoakTarget& target, int index, SoakClock::time_point end,
                     SoakTally& tally);
void run_trickler(const SoakTarget& target, std::chrono::milliseconds interval,
                  SoakClock::time_point end, SoakTally& tally);

}  // namespace strielad::bench
