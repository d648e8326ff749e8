// SPDX-License-Identifier: Apache-2.0
#include "bench/latency_suite.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <thread>

#include "bench/cut_client.h"
#include "view/level_heights.h"
#include "bench/machine_info.h"
#include "bench/page_cache.h"
#include "bench/server_process.h"
#include "bench/stopwatch.h"
#include "core/error.h"
#include "lod/camera_path.h"
#include "store/store.h"

namespace strielad::bench {

namespace {

using namespace std::chrono_literals;

constexpr const char* kDataset = "store";

// Clouds and ice, shaded by temperature: the paper's typical view.
Scene scene_clouds() {
  Scene s;
  s.subvolumes.push_back({1, "cloud water", {{"clw", 1e-5, std::nullopt}}, {}});
  s.subvolumes.push_back({2, "cloud ice", {{"cli", 1e-6, std::nullopt}}, {}});
  s.attributes = {"ta"};
  return s;
}

// Another parameter set: thicker clouds and rain in warm air (one new variable).
Scene scene_rain(std::uint32_t time) {
  Scene s;
  s.time = time;
  s.subvolumes.push_back({1, "thick cloud", {{"clw", 1e-4, std::nullopt}}, {}});
  s.subvolumes.push_back({3, "rain in warm air", {{"qr", 1e-5, std::nullopt}, {"ta", 273.15, std::nullopt}}, {}});
  s.attributes = {"ta"};
  return s;
}

CutLatency cut_latency(const CutClient& c, bool complete) {
  CutLatency l;
  l.nodes = c.cut_size();
  l.complete = complete;
  std::vector<double> t = c.arrival_seconds();
  std::sort(t.begin(), t.end());
  auto at = [&](double q) {
    if (t.empty() || l.nodes == 0) return -1.0;
    const std::size_t k = static_cast<std::size_t>(std::ceil(q * double(l.nodes)));
    return k == 0 ? t.front() : (k <= t.size() ? t[k - 1] : -1.0);
  };
  l.first = t.empty() ? -1.0 : t.front();
  l.p50 = at(0.5);
  l.p90 = at(0.9);
  l.all = complete ? at(1.0) : -1.0;
  l.meshes = c.generation_counters().meshes;
  l.skipped = c.generation_counters().skipped;
  l.arrivals = std::move(t);
  return l;
}


nlohmann::json server_stats(CutClient& c) { return nlohmann::json::parse(c.client().stats()); }

// Waits until the server has nothing queued or running and its prefetching has stopped
// making progress (or `limit` passed). Returns the seconds waited.
double wait_server_idle(CutClient& c, double limit_s) {
  const Stopwatch clock;
  std::uint64_t last_prefetch = ~0ull;
  int stable = 0;
  while (clock.seconds() < limit_s) {
    const auto s = server_stats(c);
    const auto prefetch = s["prefetch"]["nodes"].get<std::uint64_t>();
    const bool idle = s["queued"].get<std::int64_t>() == 0 && s["running"].get<std::int64_t>() == 0;
    stable = idle && prefetch == last_prefetch ? stable + 1 : 0;
    if (stable >= 3) break;
    last_prefetch = prefetch;
    c.pump(100ms);
  }
  return clock.seconds();
}

serve::ServerConfig server_config(const LatencySuiteOptions& o, bool prefetch, std::size_t clients) {
  serve::ServerConfig config;
  config.root = o.work / "root";
  config.threads = o.threads;
  config.cache_bytes = o.cache_mib << 20;
  config.prefetch = prefetch;
  config.max_clients = clients;
  return config;
}

lod::Camera camera_at(const lod::WorldCameraPath& path, const CutClient& c, double t, double aspect) {
  return lod::pose_camera(path.sample(t), aspect, c.frame().domain());
}

struct Rig {
  const LatencySuiteOptions& o;
  std::unique_ptr<lod::WorldCameraPath> path;
  std::filesystem::path log_dir;
  int servers = 0;

  std::unique_ptr<BenchServer> start(bool prefetch, std::size_t clients = 4) {
    return std::make_unique<BenchServer>(
        o.server_binary, server_config(o, prefetch, clients),
        log_dir / fmt::format("server-{}.log", servers++));
  }
  net::Endpoint at(const BenchServer& s) const { return {"127.0.0.1", s.port()}; }
};

void run_fly_in(Rig& rig, LatencySuiteReport& report) {
  const LatencySuiteOptions& o = rig.o;
  auto server = rig.start(true);
  CutClient c(rig.at(*server), kDataset, {}, "bench fly-in");
  c.move(camera_at(*rig.path, c, rig.path->start_time(), o.aspect));
  const Clock::time_point origin = c.set_scene(scene_clouds());
  const double duration = rig.path->end_time() - rig.path->start_time();
  const auto frame = std::chrono::duration<double>(1.0 / o.fps);
  double next_sample = 0;
  for (std::size_t k = 0;; ++k) {
    const double t = double(k) / o.fps;
    if (t > duration) break;
    std::this_thread::sleep_until(origin + std::chrono::duration_cast<Clock::duration>(frame * double(k)));
    c.move(camera_at(*rig.path, c, rig.path->start_time() + t, o.aspect));
    c.pump();
    report.fly_in_max_cut = std::max(report.fly_in_max_cut, c.cut_size());
    if (t >= next_sample) {
      report.fly_in.push_back({t, c.cut_size(), c.answered_in_cut()});
      next_sample += 0.25;
    }
  }
  const Stopwatch after;
  const bool complete = c.wait_complete(60s);
  report.fly_in_complete_after_stop_s = complete ? after.seconds() : -1.0;
  report.fly_in.push_back({duration + after.seconds(), c.cut_size(), c.answered_in_cut()});
}

void run_phases(Rig& rig, LatencySuiteReport& report, const EvictableFolder& files) {
  const LatencySuiteOptions& o = rig.o;
  PhaseLatency cold{"cold start", false, {}}, cold_pf{"cold start", true, {}};
  PhaseLatency time_on{"time change", true, {}}, time_off{"time change", false, {}};
  PhaseLatency scene_on{"scene change", true, {}}, scene_off{"scene change", false, {}};
  std::uint64_t bytes = 0, results = 0;
  double hit_rate_sum = 0;
  int hit_rate_n = 0;
  double prefetch_wait = 1.0;
  for (int round = 0; round < o.repeat; ++round) {
    for (bool prefetch : {true, false}) {
      if (o.evict) files.evict();
      auto server = rig.start(prefetch);
      CutClient c(rig.at(*server), kDataset, {}, "bench phases");
      c.move(camera_at(*rig.path, c, rig.path->end_time(), o.aspect));
      const auto timeout = 120s;
      c.set_scene(scene_clouds());
      (prefetch ? cold_pf : cold).rounds.push_back(cut_latency(c, c.wait_complete(timeout)));
      // The same idle time for both modes: what prefetching took, at least a second.
      if (prefetch) {
        prefetch_wait = std::max(1.0, wait_server_idle(c, 60));
      } else {
        const Stopwatch idle;
        while (idle.seconds() < prefetch_wait) c.pump(50ms);
      }
      c.set_time(1);
      (prefetch ? time_on : time_off).rounds.push_back(cut_latency(c, c.wait_complete(timeout)));
      c.set_scene(scene_rain(1));
      (prefetch ? scene_on : scene_off).rounds.push_back(cut_latency(c, c.wait_complete(timeout)));
      const auto stats = server_stats(c);
      hit_rate_sum += stats["cache"]["hit_rate"].get<double>();
      ++hit_rate_n;
      bytes += c.client().bytes_received();
      results += c.counters().results + c.counters().failed;
    }
  }
  report.phases = {cold_pf, cold, scene_on, scene_off, time_on, time_off};
  report.bytes_per_node = results ? double(bytes) / double(results) : 0;
  report.cache_hit_rate = hit_rate_n ? hit_rate_sum / hit_rate_n : 0;
}

void run_rapid(Rig& rig, LatencySuiteReport& report) {
  const LatencySuiteOptions& o = rig.o;
  auto server = rig.start(true);
  CutClient c(rig.at(*server), kDataset, {}, "bench rapid");
  c.move(camera_at(*rig.path, c, rig.path->end_time(), o.aspect));
  c.set_scene(scene_clouds());
  RapidChanges& r = report.rapid;
  r.cut = c.cut_size();
  const auto interval = std::chrono::duration<double, std::milli>(o.rapid_interval_ms);
  const Clock::time_point start = Clock::now();
  std::uint32_t step = 0;
  Clock::time_point next_stats = start;
  for (std::size_t k = 1;; ++k) {
    const auto deadline = start + std::chrono::duration_cast<Clock::duration>(interval * double(k));
    while (Clock::now() < deadline) {
      c.pump(std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()));
    }
    if (k > 1) {
      const auto t = c.arrival_seconds();
      if (!t.empty()) {
        ++r.answered;
        r.first_latency_s.push_back(*std::min_element(t.begin(), t.end()));
      }
    }
    if (Clock::now() >= next_stats) {
      r.max_queued = std::max(r.max_queued, server_stats(c)["queued"].get<std::int64_t>());
      next_stats = Clock::now() + 500ms;
    }
    if (std::chrono::duration<double>(Clock::now() - start).count() >= o.rapid_seconds) break;
    step = step ? 0 : 1;
    c.set_time(step);
    ++r.generations;
  }
  const bool complete = c.wait_complete(120s);
  r.final_complete = complete;
  r.final_all_s = cut_latency(c, complete).all;
  r.stale = c.client().stale_results();
}

void run_concurrent(Rig& rig, LatencySuiteReport& report) {
  const LatencySuiteOptions& o = rig.o;
  ConcurrentClients& cc = report.concurrent;
  cc.clients = o.clients;
  cc.budget_bytes = o.cache_mib << 20;
  auto server = rig.start(true, static_cast<std::size_t>(o.clients) + 1);
  std::atomic<std::uint64_t> results{0}, failed{0}, errors{0}, disconnects{0}, stale{0}, generations{0};
  const Clock::time_point end = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                   std::chrono::duration<double>(o.clients_seconds));
  std::vector<std::thread> threads;
  for (int i = 0; i < o.clients; ++i) {
    threads.emplace_back([&, i] {
      try {
        CutClient c(rig.at(*server), kDataset, {}, fmt::format("bench client {}", i));
        const double span = rig.path->end_time() - rig.path->start_time();
        double t = rig.path->start_time() + span * double(i) / double(o.clients);
        c.move(camera_at(*rig.path, c, t, o.aspect));
        if (i % 2) {
          c.set_scene(scene_clouds());
        } else {
          c.set_scene(scene_rain(0));
        }
        ++generations;
        std::uint32_t step = 0;
        Clock::time_point next_time = Clock::now() + 2s;
        while (Clock::now() < end) {
          c.pump(100ms);
          t += 0.1;
          if (t > rig.path->end_time()) t = rig.path->start_time();
          c.move(camera_at(*rig.path, c, t, o.aspect));
          if (Clock::now() >= next_time) {
            step = step ? 0 : 1;
            c.set_time(step);
            ++generations;
            next_time = Clock::now() + 2s;
          }
        }
        results += c.counters().results;
        failed += c.counters().failed;
        errors += c.counters().errors;
        stale += c.client().stale_results();
      } catch (const Error& e) {
        spdlog::warn("bench: concurrent client {}: {}", i, e.what());
        ++disconnects;
      }
    });
  }
  for (auto& t : threads) t.join();
  cc.seconds = o.clients_seconds;
  cc.results = results;
  cc.failed = failed;
  cc.errors = errors;
  cc.disconnects = disconnects;
  cc.stale = stale;
  cc.generations = generations;
  cc.memory_measured = !server->in_process();
  cc.peak_rss_bytes = server->memory().peak_rss_bytes;
}

}  // namespace

LatencySuiteOptions quick_latency_options(LatencySuiteOptions o) {
  o.dims = {60, 56, 30};
  o.brick = 8;
  o.fly_seconds = 1;
  o.fps = 30;
  o.repeat = 1;
  o.rapid_seconds = 0.5;
  o.clients = 3;
  o.clients_seconds = 1;
  o.cache_mib = 64;
  o.evict = false;
  return o;
}

LatencySuiteReport run_latency_suite(const LatencySuiteOptions& o) {
  if (o.repeat < 1 || o.clients < 1 || !(o.fps > 0) || !(o.rapid_interval_ms > 0)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "latency suite: repeat, clients, fps and the change interval must be > 0");
  }
  if (o.steps < 2) {
    throw make_error(ErrorCode::kInvalidArgument, "latency suite: needs at least 2 time steps");
  }
  const Stopwatch suite;
  LatencySuiteReport report;
  report.options = o;
  std::filesystem::create_directories(o.work / "root");
  std::filesystem::create_directories(o.work / "logs");
  report.machine = machine_info(o.work);
  report.input = ensure_sample_input({o.dims, o.steps, o.variables, o.seed}, o.work / "input");
  const Stopwatch convert_clock;
  const auto store_dir = o.work / "root" / kDataset;
  spdlog::info("bench: converting into {} (brick {})", store_dir.string(), o.brick);
  convert_sample_store(report.input, o.variables, o.brick, o.convert_threads, store_dir);
  report.convert_seconds = convert_clock.seconds();
  const auto store = Store::open(store_dir);
  report.octree_nodes = store->octree().node_count();
  const EvictableFolder files(store_dir);

  const lod::WorldFrame frame(
      store->manifest(),
      lod::WorldFrameOptions{}, view::representative_level_heights_m(*store),
      store->horizontal_coordinates());
  const lod::CameraPath path = o.camera_path.empty()
                                   ? lod::default_fly_in_path(frame, o.fly_seconds)
                                   : lod::load_camera_path_file(o.camera_path);
  Rig rig{o, std::make_unique<lod::WorldCameraPath>(
                 path, frame, o.camera_path.empty() ? "default fly-in" : o.camera_path.string()),
          o.work / "logs"};

  spdlog::info("bench: fly-in ({} s at {} fps)", o.fly_seconds, o.fps);
  if (o.evict) files.evict();
  run_fly_in(rig, report);
  spdlog::info("bench: scene and time-step changes ({} rounds, prefetch on and off)", o.repeat);
  run_phases(rig, report, files);
  spdlog::info("bench: time step changing every {} ms for {} s", o.rapid_interval_ms, o.rapid_seconds);
  run_rapid(rig, report);
  spdlog::info("bench: {} concurrent clients for {} s", o.clients, o.clients_seconds);
  run_concurrent(rig, report);
  report.machine["load_average_1min_end"] = load_average_1min();
  report.targets = evaluate_latency_targets(report);
  report.seconds = suite.seconds();
  return report;
}

}  // namespace strielad::bench
