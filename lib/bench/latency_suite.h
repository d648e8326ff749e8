// SPDX-License-Identifier: Apache-2.0
// The `strielad-bench latency` suite: a simulated
// viewer (bench/cut_client.h: the viewer's own LOD cut code) plays a camera path over
// loopback against strielad-serve on a generated time step and measures
//  - the fly-in: how complete the cut is while the camera moves, and how long after it
//    stops the cut is complete;
//  - time to the first node and to 50, 90 and 100 % of the cut after a cold start, a
//    scene change and a time-step change with and without prefetching;
//  - the newest generation's latency while the time step changes every 50 ms for 10 s
//    (stale work must be dropped, not queued);
//  - 32 concurrent clients for 60 s: errors, and the server's memory against its budget.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/io_suite.h"
#include "bench/latency_stats.h"
#include "bench/sample_input.h"
#include "bench/table_writer.h"
#include "convert/converter.h"
#include "grid/axis.h"

namespace strielad::bench {

struct LatencySuiteOptions {
  Dims3 dims{1429, 1556, 150};  // one full time step of the paper's grid
  std::size_t steps = 2;        // a time-step change needs two
  std::vector<std::string> variables{"clw", "cli", "qr", "ta"};
  std::uint64_t seed = 1;
  std::filesystem::path work = "/tmp/strielad-bench-latency";
  std::uint32_t brick = build::kDefaultBrick;
  int convert_threads = 0;
  // The server: a child process when a binary is given (found next to strielad-bench by
  // the command), in-process otherwise.
  std::filesystem::path server_binary;
  unsigned threads = 2;
  std::uint64_t cache_mib = 1024;
  // Drop the store's pages from the page cache before every cold start.
  bool evict = true;
  // Camera: a camera-path file (formats/camera-path.md) or the default fly-in.
  std::filesystem::path camera_path;
  double fly_seconds = 20;
  double fps = 60;
  double aspect = 16.0 / 9.0;
  int repeat = 3;  // cold start, scene change and time change rounds per prefetch mode
  double rapid_seconds = 10;
  double rapid_interval_ms = 50;
  int clients = 32;
  double clients_seconds = 60;
  std::string command_line;
};

// A small grid and short phases: seconds, for CI (checks the harness, not the targets).
LatencySuiteOptions quick_latency_options(LatencySuiteOptions base);

// Seconds from a generation's request to the first answer and to 50/90/100 % of the cut.
struct CutLatency {
  std::size_t nodes = 0;  // in the cut
  double first = 0, p50 = 0, p90 = 0, all = 0;
  bool complete = false;  // every node answered before the timeout
  std::uint64_t meshes = 0, skipped = 0;
  std::vector<double> arrivals;  // seconds of every answer of a node in the cut, sorted
};

struct PhaseLatency {
  std::string phase;  // "cold start", "scene change", "time change"
  bool prefetch = false;
  std::vector<CutLatency> rounds;
};

struct FlyInFrame {
  double t = 0;
  std::size_t cut = 0, answered = 0;
};

struct RapidChanges {
  std::size_t generations = 0;
  std::size_t answered = 0;              // generations that got a first answer in time
  std::vector<double> first_latency_s;   // per answered generation, in order
  std::int64_t max_queued = 0;           // largest server queue seen
  std::size_t cut = 0;
  double final_all_s = 0;                // after the last change: the whole cut
  bool final_complete = false;
  std::uint64_t stale = 0;               // results of an older generation (must be 0)
};

struct ConcurrentClients {
  int clients = 0;
  double seconds = 0;
  std::uint64_t results = 0, failed = 0, errors = 0, disconnects = 0, stale = 0;
  std::uint64_t generations = 0;
  std::uint64_t peak_rss_bytes = 0, budget_bytes = 0;
  bool memory_measured = false;  // false for an in-process server
};

struct LatencySuiteReport {
  LatencySuiteOptions options;
  nlohmann::json machine;
  SampleInput input;
  double convert_seconds = 0;
  std::size_t octree_nodes = 0;
  std::vector<FlyInFrame> fly_in;
  double fly_in_complete_after_stop_s = -1;  // -1: not within the timeout
  std::size_t fly_in_max_cut = 0;
  std::vector<PhaseLatency> phases;
  double bytes_per_node = 0;
  double cache_hit_rate = 0;  // server's, after the warm phases
  RapidChanges rapid;
  ConcurrentClients concurrent;
  std::vector<Target> targets;
  double seconds = 0;
};

// \error as the generator, the converter, the server and the client.
LatencySuiteReport run_latency_suite(const LatencySuiteOptions& options);

std::vector<Target> evaluate_latency_targets(const LatencySuiteReport& report);
std::vector<Table> latency_report_tables(const LatencySuiteReport& report);
nlohmann::json latency_report_json(const LatencySuiteReport& report,
                                   const std::vector<Table>& tables);

}  // namespace strielad::bench
