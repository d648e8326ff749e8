// SPDX-License-Identifier: Apache-2.0
#include "bench/scaling_suite.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "bench/cut_client.h"
#include "view/level_heights.h"
#include "bench/machine_info.h"
#include "bench/page_cache.h"
#include "bench/sample_input.h"
#include "bench/scene_economy.h"
#include "bench/server_process.h"
#include "bench/stopwatch.h"
#include "core/error.h"
#include "store/store.h"

namespace strielad::bench {
namespace {

using namespace std::chrono_literals;

std::pair<double, double> axis_range(const Axis& axis) {
  const auto [lo, hi] = std::minmax_element(axis.values.begin(), axis.values.end());
  return {*lo, *hi};
}

// Eight sub-volumes of the kind users combine: sparse fields alone, with a dense limit,
// inside a region, and layers of a dense field. The first two are the clouds scene the
// grid and thread runs use (the latency suite's typical view).
std::vector<std::string> subvolume_json(const format::Manifest& m) {
  const auto [x0, x1] = axis_range(m.x);
  const auto [y0, y1] = axis_range(m.y);
  const double xm = 0.5 * (x0 + x1), ym = 0.5 * (y0 + y1);
  return {
      R"({"id":1,"name":"cloud water","limits":[{"var":"clw","min":1e-5}]})",
      R"({"id":2,"name":"cloud ice","limits":[{"var":"cli","min":1e-6}]})",
      R"({"id":3,"name":"rain in warm air","limits":[{"var":"qr","min":1e-5},{"var":"ta","min":273.15}]})",
      R"({"id":4,"name":"cold layer","limits":[{"var":"ta","min":250,"max":255}]})",
      fmt::format(R"({{"id":5,"name":"thick cloud west","limits":[{{"var":"clw","min":1e-4}}],)"
                  R"("domain":{{"{}":[{},{}]}}}})",
                  m.x.name, x0, xm),
      R"({"id":6,"name":"ice in cold air","limits":[{"var":"cli","min":1e-5},{"var":"ta","max":240}]})",
      fmt::format(R"({{"id":7,"name":"drizzle south","limits":[{{"var":"qr","min":1e-6}}],)"
                  R"("domain":{{"{}":[{},{}]}}}})",
                  m.y.name, y0, ym),
      fmt::format(R"({{"id":8,"name":"freezing layer in a box","limits":[{{"var":"ta","min":270,"max":275}}],)"
                  R"("domain":{{"{}":[{},{}],"{}":[{},{}]}}}})",
                  m.x.name, 0.75 * x0 + 0.25 * x1, 0.25 * x0 + 0.75 * x1, m.y.name,
                  0.75 * y0 + 0.25 * y1, 0.25 * y0 + 0.75 * y1),
  };
}

Scene scene_of(const format::Manifest& m, int count) {
  const auto all = subvolume_json(m);
  if (count < 1 || count > static_cast<int>(all.size())) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "scaling: {} sub-volumes asked for, the suite has 1 to {}", count, all.size());
  }
  std::vector<std::string> picked(all.begin(), all.begin() + count);
  return parse_scene(fmt::format(R"({{"subvolumes":[{}],"attributes":["ta"]}})",
                                 fmt::join(picked, ",")),
                     fmt::format("scaling scene of {} sub-volume(s)", count));
}

std::string grid_name(Dims3 d) { return fmt::format("{}x{}x{}", d.x, d.y, d.z); }

std::uint64_t folder_bytes(const std::filesystem::path& dir) {
  std::uint64_t bytes = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
    if (e.is_regular_file()) bytes += e.file_size();
  }
  return bytes;
}

// Converts `repeat` times into a fresh folder (the last one is kept) and times it.
Summary timed_conversions(const SampleInput& input, const ScalingSuiteOptions& o, int threads,
                         const std::filesystem::path& store_dir) {
  std::vector<double> seconds;
  for (int r = 0; r < o.repeat; ++r) {
    std::filesystem::remove_all(store_dir);
    const Stopwatch clock;
    convert_sample_store(input, o.variables, o.brick, threads, store_dir);
    seconds.push_back(clock.seconds());
  }
  return summarize(seconds);
}

Summary timed_batches(const std::filesystem::path& store_dir, const Scene& scene,
                     const std::vector<NodeId>& nodes, int threads, int repeat,
                     NodeBatchCost& last) {
  std::vector<double> seconds;
  for (int r = 0; r < repeat; ++r) {
    last = run_node_batch(store_dir, scene, nodes, threads);
    seconds.push_back(last.seconds);
  }
  return summarize(seconds);
}

int most_threads(const ScalingSuiteOptions& o) {
  return o.threads.empty() ? 0 : *std::max_element(o.threads.begin(), o.threads.end());
}

GridScaling measure_grid(const ScalingSuiteOptions& o, double fraction,
                         std::filesystem::path& store_dir) {
  GridScaling g;
  g.fraction = fraction;
  g.dims = fraction_of_grid(o.dims, fraction);
  const std::string name = grid_name(g.dims);
  const auto input =
      ensure_sample_input({g.dims, 1, o.variables, o.seed}, o.work / ("input-" + name));
  g.input_bytes = input.bytes;
  store_dir = o.work / "root" / ("store-" + name);
  for (const int threads : o.threads) {
    spdlog::info("scaling: converting {} with {} thread(s)", name, threads);
    g.convert.push_back({threads, timed_conversions(input, o, threads, store_dir)});
  }
  if (o.threads.empty()) convert_sample_store(input, o.variables, o.brick, 0, store_dir);
  g.store_bytes = folder_bytes(store_dir);
  const auto store = Store::open(store_dir);
  g.octree_nodes = store->octree().node_count();
  const auto leaves = level_nodes(store->octree(), 0);
  g.leaves = leaves.size();
  const Scene clouds = scene_of(store->manifest(), 2);
  for (const int threads : o.threads) {
    spdlog::info("scaling: level 0 of {} with {} thread(s)", name, threads);
    g.level.push_back({threads, timed_batches(store_dir, clouds, leaves, threads, o.repeat,
                                              g.level_cost)});
  }
  const lod::WorldFrame frame(
      store->manifest(),
      lod::WorldFrameOptions{}, view::representative_level_heights_m(*store),
      store->horizontal_coordinates());
  const auto overview = typical_cameras(frame, o.aspect).front().camera;
  g.cut_seconds = timed_batches(store_dir, clouds, cut_nodes(*store, frame, overview),
                                most_threads(o), o.repeat, g.cut_cost);
  return g;
}


// Seconds after the request until the first answer, half the cut and all of it (-1 when
// the cut did not complete).
struct CutTimes {
  double first = -1, half = -1, all = -1;
};

CutTimes cut_times(const CutClient& c, bool complete) {
  std::vector<double> t = c.arrival_seconds();
  std::sort(t.begin(), t.end());
  CutTimes out;
  if (t.empty()) return out;
  out.first = t.front();
  const std::size_t half = (c.cut_size() + 1) / 2;
  if (half >= 1 && half <= t.size()) out.half = t[half - 1];
  if (complete) out.all = t.back();
  return out;
}

ServerScaling measure_server(const ScalingSuiteOptions& o, const ServerLayout& layout,
                             const std::filesystem::path& root, const std::string& dataset,
                             const EvictableFolder& files) {
  ServerScaling s;
  s.layout = layout;
  if (o.server_binary.empty()) {
    s.skipped = "no strielad-serve binary next to strielad-bench";
    return s;
  }
  std::vector<std::string> launcher;
  if (layout.ranks > 1) {
    if (o.mpirun.empty()) {
      s.skipped = "mpirun not found (package openmpi-bin)";
      return s;
    }
    launcher = {o.mpirun.string(), "--allow-run-as-root", "--oversubscribe", "--bind-to", "none",
                "-np", std::to_string(layout.ranks)};
  }
  serve::ServerConfig config;
  config.root = root;
  config.threads = static_cast<unsigned>(layout.threads);
  config.cache_bytes = o.cache_mib << 20;
  config.max_clients = 4;
  std::vector<double> first, half, all, scene_all;
  for (int r = 0; r < o.repeat; ++r) {
    files.evict();
    const auto log = o.work / fmt::format("server-{}x{}-{}.log", layout.ranks, layout.threads, r);
    std::optional<BenchServer> started;
    try {
      started.emplace(o.server_binary, config, log, launcher);
    } catch (const Error& e) {
      // An installed mpirun that cannot start jobs here (no slots, no network, a broken
      // Open MPI) costs this layout only; a threaded server that fails is a real failure.
      if (launcher.empty()) throw;
      spdlog::warn("scaling: {} rank(s) x {} thread(s) skipped: {}", layout.ranks, layout.threads,
                   e.what());
      s.skipped = fmt::format("mpirun did not start the server ({}; log {})", e.what(),
                              log.string());
      return s;
    }
    BenchServer& server = *started;
    CutClient c({"127.0.0.1", server.port()}, dataset, {}, "bench scaling");
    c.move(typical_cameras(c.frame(), o.aspect).front().camera);
    s.cut = c.cut_size();
    c.set_scene(scene_of(c.client().manifest(), 2));
    const bool cold_complete = c.wait_complete(180s);
    const CutTimes cold = cut_times(c, cold_complete);
    Scene other = scene_of(c.client().manifest(), 4);
    other.subvolumes.erase(other.subvolumes.begin(), other.subvolumes.begin() + 2);
    c.set_scene(other);
    const bool scene_complete = c.wait_complete(180s);
    const CutTimes changed = cut_times(c, scene_complete);
    ++s.rounds;
    if (cold_complete && scene_complete) {
      ++s.complete;
      first.push_back(cold.first);
      half.push_back(cold.half);
      all.push_back(cold.all);
      scene_all.push_back(changed.all);
    }
    server.stop();
  }
  s.cold_first = summarize(first);
  s.cold_half = summarize(half);
  s.cold_all = summarize(all);
  s.scene_all = summarize(scene_all);
  return s;
}

}  // namespace

ScalingSuiteOptions quick_scaling_options(ScalingSuiteOptions o) {
  o.dims = {96, 88, 30};
  o.brick = 8;
  o.repeat = 1;
  o.layouts = {{1, 1}, {1, 2}, {2, 1}};
  o.cache_mib = 64;
  return o;
}

Dims3 fraction_of_grid(Dims3 full, double fraction) {
  if (!(fraction > 0) || fraction > 1) {
    throw make_error(ErrorCode::kInvalidArgument, "grid fraction {} is not in (0, 1]", fraction);
  }
  const double s = std::sqrt(fraction);
  auto scaled = [&](std::size_t n) {
    return std::max<std::size_t>(2, static_cast<std::size_t>(std::lround(double(n) * s)));
  };
  return {scaled(full.x), scaled(full.y), full.z};
}

ScalingSuiteReport run_scaling_suite(const ScalingSuiteOptions& o) {
  if (o.repeat < 1) throw make_error(ErrorCode::kInvalidArgument, "scaling: --repeat must be >= 1");
  if (o.fractions.empty()) throw make_error(ErrorCode::kInvalidArgument, "scaling: no grid fraction");
  const Stopwatch clock;
  ScalingSuiteReport report;
  report.options = o;
  std::vector<double> fractions = o.fractions;
  std::sort(fractions.begin(), fractions.end());
  std::filesystem::path smallest_store;
  for (const double f : fractions) {
    std::filesystem::path store_dir;
    report.grids.push_back(measure_grid(o, f, store_dir));
    if (smallest_store.empty()) smallest_store = store_dir;
  }
  // The server's root holds every grid's store; the client opens the smallest.
  const EvictableFolder files(smallest_store);
  for (const ServerLayout& layout : o.layouts) {
    spdlog::info("scaling: server with {} rank(s) x {} thread(s)", layout.ranks, layout.threads);
    report.servers.push_back(
        measure_server(o, layout, o.work / "root", smallest_store.filename().string(), files));
  }
  const auto store = Store::open(smallest_store);
  const auto leaves = level_nodes(store->octree(), 0);
  for (const int count : o.subvolume_counts) {
    spdlog::info("scaling: {} sub-volume(s)", count);
    SubvolumeScaling s;
    s.count = count;
    s.seconds = timed_batches(smallest_store, scene_of(store->manifest(), count), leaves,
                              most_threads(o), o.repeat, s.cost);
    report.subvolumes.push_back(s);
  }
  report.machine = machine_info(o.work);
  report.seconds = clock.seconds();
  return report;
}

}  // namespace strielad::bench
