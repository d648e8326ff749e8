// SPDX-License-Identifier: Apache-2.0
// The `strielad-bench soak` suite ("The server's memory and connection slots
// are bounded"): strielad-serve as a child process on loopback against normal clients
// doing real work in a loop, slow readers that send requests and never read, and
// tricklers that send a handshake byte every few seconds (bench/soak_clients.h), for a
// fixed time. It samples the server's RSS (/proc) and its slot use (Stats) over time:
// both must stay flat, and normal clients must keep getting their answers.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/sample_input.h"
#include "bench/table_writer.h"
#include "grid/axis.h"

namespace strielad::bench {

struct SoakSuiteOptions {
  Dims3 dims{96, 96, 40};
  std::size_t steps = 1;
  std::vector<std::string> variables{"clw", "cli", "ta"};
  std::uint64_t seed = 1;
  std::uint32_t brick = 16;
  std::filesystem::path work = "/tmp/strielad-bench-soak";
  // A child process when a binary is given, in-process otherwise (RSS is then the whole
  // benchmark's).
  std::filesystem::path server_binary;
  unsigned threads = 2;
  std::uint64_t cache_mib = 256;
  // The server's limits (strielad-serve --max-clients, --max-handshakes,
  // --handshake-timeout, --max-send-queue-mib).
  std::size_t max_clients = 64;
  std::size_t max_handshakes = 64;
  double handshake_timeout_s = 10;
  double send_queue_mib = 8;
  int clients = 32;
  int slow_readers = 16;
  int tricklers = 64;
  double trickle_interval_s = 5;
  double seconds = 150;
  double sample_seconds = 10;
  std::string command_line;
};

// A small grid, few clients and a few seconds: checks the harness (CI).
SoakSuiteOptions quick_soak_options(SoakSuiteOptions base);

// One look at the server. Stats keys an older server lacks are -1.
struct SoakSample {
  double t = 0;
  std::uint64_t rss_bytes = 0;
  std::int64_t clients = -1, handshakes = -1, readers_paused = -1, send_queue_bytes = -1;
  std::int64_t connections_rejected = -1, handshakes_dropped = -1;
  bool stats_answered = false;  // the monitor got Stats within its timeout
  // The harness's clients so far.
  std::uint64_t rounds = 0, answers = 0, errors = 0, refused = 0;
  std::uint64_t slow_requests = 0, trickler_connections = 0, tricklers_closed = 0;
};

struct SoakKindTotals {
  std::string kind;  // "normal", "slow reader", "trickler"
  int count = 0;
  std::uint64_t connections = 0, rounds = 0, answers = 0, requests = 0, refused = 0, errors = 0,
                closed_by_server = 0;
};

struct SoakSuiteReport {
  SoakSuiteOptions options;
  nlohmann::json machine;
  SampleInput input;
  std::size_t octree_nodes = 0;
  bool memory_measured = false;  // false for an in-process server
  std::vector<SoakSample> samples;  // the first before any client started
  std::vector<SoakKindTotals> kinds;
  std::uint64_t rss_start = 0, rss_max = 0, rss_end = 0;
  std::int64_t rss_second_half_growth = 0;  // end minus the sample at half time
  std::int64_t max_clients_used = -1, max_handshakes_used = -1;  // -1: not reported
  double seconds = 0;
};

// \error as the generator, the converter, the server and the monitor's connection.
SoakSuiteReport run_soak_suite(const SoakSuiteOptions& options);
std::vector<Table> soak_report_tables(const SoakSuiteReport& report);
nlohmann::json soak_report_json(const SoakSuiteReport& report, const std::vector<Table>& tables);

}  // namespace strielad::bench
