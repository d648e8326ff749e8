// SPDX-License-Identifier: Apache-2.0
#include "bench/soak_suite.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <thread>

#include "bench/machine_info.h"
#include "bench/server_process.h"
#include "bench/soak_clients.h"
#include "bench/stopwatch.h"
#include "client/server_client.h"
#include "core/error.h"
#include "store/store.h"

namespace strielad::bench {

namespace {

using namespace std::chrono_literals;

constexpr const char* kDataset = "store";

std::chrono::milliseconds millis(double seconds) {
  return std::chrono::milliseconds(static_cast<std::int64_t>(seconds * 1000));
}

serve::ServerConfig server_config(const SoakSuiteOptions& o) {
  serve::ServerConfig config;
  config.root = o.work / "root";
  config.threads = o.threads;
  config.cache_bytes = o.cache_mib << 20;
  config.max_clients = o.max_clients;
  config.max_handshakes = o.max_handshakes;
  config.handshake_timeout = millis(o.handshake_timeout_s);
  config.max_pending_send_bytes = static_cast<std::uint64_t>(o.send_queue_mib * (1 << 20));
  return config;
}

std::int64_t key_or(const nlohmann::json& j, const char* key) {
  return j.contains(key) ? j[key].get<std::int64_t>() : -1;
}

SoakSample look(double t, const BenchServer& server, client::ServerClient& monitor,
                std::chrono::milliseconds timeout, const SoakTally& normal,
                const SoakTally& slow, const SoakTally& trickle) {
  SoakSample s;
  s.t = t;
  s.rss_bytes = server.memory().rss_bytes;
  try {
    const auto j = nlohmann::json::parse(monitor.stats(timeout));
    s.stats_answered = true;
    s.clients = key_or(j, "clients");
    s.handshakes = key_or(j, "handshakes");
    s.readers_paused = key_or(j, "readers_paused");
    s.send_queue_bytes = key_or(j, "send_queue_bytes");
    s.connections_rejected = key_or(j, "connections_rejected");
    s.handshakes_dropped = key_or(j, "handshakes_dropped");
  } catch (const Error& e) {
    spdlog::warn("bench: soak monitor: {}", e.what());
  }
  s.rounds = normal.rounds;
  s.answers = normal.answers;
  s.errors = normal.errors;
  s.refused = normal.refused;
  s.slow_requests = slow.requests;
  s.trickler_connections = trickle.connections;
  s.tricklers_closed = trickle.closed_by_server;
  return s;
}

SoakKindTotals totals(std::string kind, int count, const SoakTally& t) {
  return {std::move(kind), count, t.connections, t.rounds, t.answers, t.requests, t.refused,
          t.errors, t.closed_by_server};
}

void summarize(SoakSuiteReport& r) {
  if (r.samples.empty()) return;
  r.rss_start = r.samples.front().rss_bytes;
  r.rss_end = r.samples.back().rss_bytes;
  const double half = r.samples.back().t / 2;
  const auto mid = std::find_if(r.samples.begin(), r.samples.end(),
                                [&](const SoakSample& s) { return s.t >= half; });
  r.rss_second_half_growth =
      static_cast<std::int64_t>(r.rss_end) - static_cast<std::int64_t>(mid->rss_bytes);
  for (const SoakSample& s : r.samples) {
    r.rss_max = std::max(r.rss_max, s.rss_bytes);
    r.max_clients_used = std::max(r.max_clients_used, s.clients);
    r.max_handshakes_used = std::max(r.max_handshakes_used, s.handshakes);
  }
}

}  // namespace

SoakSuiteOptions quick_soak_options(SoakSuiteOptions o) {
  o.dims = {40, 36, 20};
  o.brick = 8;
  o.cache_mib = 64;
  o.clients = 3;
  o.slow_readers = 2;
  o.tricklers = 6;
  // Room for every connection's handshake at once (6 tricklers, 3 + 2 clients, the
  // monitor): all connect in the same millisecond at the start, and with a smaller pool
  // a trickler's arrival may close a normal client's handshake as the oldest (the
  // documented limit of the pool, checked in server_bounds_test); here the tricklers
  // are closed by the 1 s deadline.
  o.max_handshakes = 12;
  o.handshake_timeout_s = 1;
  o.trickle_interval_s = 0.3;
  o.send_queue_mib = 1;
  o.seconds = 6;
  o.sample_seconds = 1;
  return o;
}

SoakSuiteReport run_soak_suite(const SoakSuiteOptions& o) {
  if (o.clients < 0 || o.slow_readers < 0 || o.tricklers < 0 || !(o.seconds > 0) ||
      !(o.sample_seconds > 0) || !(o.trickle_interval_s > 0)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "soak suite: client counts must be >= 0, durations and intervals > 0");
  }
  const Stopwatch suite;
  SoakSuiteReport report;
  report.options = o;
  std::filesystem::create_directories(o.work / "root");
  std::filesystem::create_directories(o.work / "logs");
  report.machine = machine_info(o.work);
  report.input = ensure_sample_input({o.dims, o.steps, o.variables, o.seed}, o.work / "input");
  const auto store_dir = o.work / "root" / kDataset;
  convert_sample_store(report.input, o.variables, o.brick, 0, store_dir);
  report.octree_nodes = Store::open(store_dir)->octree().node_count();

  BenchServer server(o.server_binary, server_config(o), o.work / "logs" / "server.log");
  report.memory_measured = !server.in_process();
  const SoakTarget target{{"127.0.0.1", server.port()}, kDataset, report.octree_nodes, 20s};
  client::ClientOptions monitor_options;
  monitor_options.client_name = "soak monitor";
  auto monitor = client::ServerClient::connect(target.endpoint, monitor_options);
  const auto sample_timeout = std::max(millis(o.sample_seconds), std::chrono::milliseconds(1000));

  SoakTally normal, slow, trickle;
  const Stopwatch clock;
  report.samples.push_back(look(0, server, *monitor, sample_timeout, normal, slow, trickle));
  const SoakClock::time_point end = SoakClock::now() + millis(o.seconds);
  spdlog::info("bench: soak for {} s: {} clients, {} slow readers, {} tricklers", o.seconds,
               o.clients, o.slow_readers, o.tricklers);
  std::vector<std::thread> threads;
  for (int i = 0; i < o.tricklers; ++i) {
    threads.emplace_back([&] { run_trickler(target, millis(o.trickle_interval_s), end, trickle); });
  }
  for (int i = 0; i < o.slow_readers; ++i) {
    threads.emplace_back([&, i] { run_slow_reader(target, i, end, slow); });
  }
  for (int i = 0; i < o.clients; ++i) {
    threads.emplace_back([&, i] { run_normal_client(target, i, end, normal); });
  }
  for (double next = o.sample_seconds; SoakClock::now() < end; next += o.sample_seconds) {
    while (clock.seconds() < next && SoakClock::now() < end) std::this_thread::sleep_for(50ms);
    report.samples.push_back(look(clock.seconds(), server, *monitor, sample_timeout, normal, slow, trickle));
    const SoakSample& s = report.samples.back();
    spdlog::info("bench: soak {:.0f} s: RSS {:.1f} MiB, {} clients, {} handshakes, {} paused, "
                 "{} rounds, {} errors, {} refused",
                 s.t, double(s.rss_bytes) / (1 << 20), s.clients, s.handshakes, s.readers_paused,
                 s.rounds, s.errors, s.refused);
  }
  for (auto& t : threads) t.join();
  report.kinds = {totals("normal", o.clients, normal), totals("slow reader", o.slow_readers, slow),
                  totals("trickler", o.tricklers, trickle)};
  summarize(report);
  monitor.reset();
  server.stop();
  report.machine["load_average_1min_end"] = load_average_1min();
  report.seconds = suite.seconds();
  return report;
}

}  // namespace strielad::bench
