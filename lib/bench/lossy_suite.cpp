// SPDX-License-Identifier: Apache-2.0
#include "bench/lossy_suite.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "bench/brick_read_bench.h"
#include "bench/conversion_bench.h"
#include "bench/machine_info.h"
#include "bench/process_runner.h"
#include "bench/stopwatch.h"
#include "bench/store_sizes.h"
#include "core/error.h"
#include "store/store.h"

namespace strielad::bench {

LossySuiteOptions quick_lossy_options(LossySuiteOptions o) {
  o.dims = {48, 40, 24};
  o.fractions = {1e-3, 1e-2};
  o.repeat = 1;
  o.reads = 20;
  o.brick = 12;
  o.quick = true;
  return o;
}

double LossyStoreRun::mb_per_s() const {
  const double s = median(convert_seconds);
  return s > 0 ? static_cast<double>(input_bytes) / 1e6 / s : 0.0;
}

namespace {

struct ErrorSums {
  double max = 0, sum2 = 0;
  std::uint64_t count = 0;
};

// Level-0 error of `lossy` against `exact` for variable v, step 0, over valid samples.
ErrorSums level0_error(const Store& exact, const Store& lossy, std::uint32_t v) {
  const std::size_t nodes = exact.octree().level(0).node_count();
  std::vector<ErrorSums> per(nodes);
  tbb::parallel_for(std::size_t{0}, nodes, [&](std::size_t n) {
    const Brick a = exact.read_brick(0, v, static_cast<NodeId>(n));
    const Brick b = lossy.read_brick(0, v, static_cast<NodeId>(n));
    ErrorSums& e = per[n];
    for (std::size_t i = 0; i < a.sample_count(); ++i) {
      const double x = a.sample(i);
      if (std::isnan(x)) continue;
      const double d = std::abs(b.sample(i) - x);
      e.max = std::max(e.max, d);
      e.sum2 += d * d;
      ++e.count;
    }
  });
  ErrorSums total;
  for (const ErrorSums& e : per) {
    total.max = std::max(total.max, e.max);
    total.sum2 += e.sum2;
    total.count += e.count;
  }
  return total;
}

std::string fraction_label(double fraction) {
  return fraction == 0 ? std::string("lossless") : fmt::format("{:g} of range", fraction);
}

// Converts into `dir` `repeat` times (each from scratch), keeping the times.
build::ConvertResult timed_conversions(const LossySuiteOptions& o, const SampleInput& input,
                                       const std::vector<build::LossyRequest>& lossy,
                                       const std::filesystem::path& dir, LossyStoreRun& run) {
  build::ConvertResult result;
  for (int r = 0; r < std::max(1, o.repeat); ++r) {
    std::filesystem::remove_all(dir);
    build::ConvertOptions co;
    co.inputs = input.files;
    co.store = dir;
    co.scan.variables = o.variables;
    co.brick = o.brick;
    co.threads = o.threads;
    co.lossy = lossy;
    const Stopwatch clock;
    result = build::convert(co);
    run.convert_seconds.push_back(clock.seconds());
  }
  run.input_bytes = result.input_bytes;
  run.zfp_bricks = result.lossy;
  run.fallback_bricks = result.lossy_fallback;
  run.data_bricks = result.data;
  return result;
}

Summary cold_reads(const LossySuiteOptions& o, const std::filesystem::path& store) {
  BrickReadOptions ro;
  ro.store = store;
  ro.reads = o.reads;
  ro.first_brick_reads = 1;
  ro.scratch = o.work;
  ro.coarse_set = false;
  const BrickReadBench b = run_brick_read_bench(ro);
  const ReadSet* set = b.find("store cold, level 0");
  return set ? set->latency() : Summary{};
}

}  // namespace

LossySuiteReport run_lossy_suite(const LossySuiteOptions& options) {
  if (options.fractions.empty() || options.variables.empty()) {
    throw make_error(ErrorCode::kInvalidArgument, "lossy suite: no tolerance or no variable");
  }
  for (const double f : options.fractions) {
    if (!(f > 0) || !std::isfinite(f)) {
      throw make_error(ErrorCode::kInvalidArgument, "lossy suite: tolerance fraction {} is not positive", f);
    }
  }
  const Stopwatch clock;
  LossySuiteReport report;
  report.options = options;
  const LossySuiteOptions& o = report.options;
  std::filesystem::create_directories(o.work);
  report.machine = machine_info(o.work);
  report.input = ensure_sample_input({o.dims, 1, o.variables, o.seed}, o.work / "input");

  spdlog::info("bench: lossless store, {} conversion(s)", o.repeat);
  const auto lossless_dir = o.work / "store-lossless";
  LossyStoreRun lossless;
  const build::ConvertResult plain = timed_conversions(o, report.input, {}, lossless_dir, lossless);
  lossless.cold_read_us = cold_reads(o, lossless_dir);
  const auto exact = Store::open(lossless_dir);
  const StoreSizes exact_sizes = measure_store_sizes(lossless_dir);
  for (const std::string& name : o.variables) {
    const auto& range = plain.summary["variables"][name];
    const double lo = range["min"].is_number() ? range["min"].get<double>() : 0.0;
    const double hi = range["max"].is_number() ? range["max"].get<double>() : 0.0;
    report.ranges.push_back({name, {lo, hi}});
    const auto* size = exact_sizes.find(name);
    lossless.variables.push_back({name, 0, 0, size ? size->store_bytes() : 0, 0, 0, 0});
  }
  report.runs.push_back(std::move(lossless));

  if (o.nccopy && find_program("nccopy")) {
    spdlog::info("bench: NetCDF-4 deflate size per variable (nccopy -V)");
    report.deflate = measure_deflate_sizes(report.input.files.front(), o.variables,
                                           o.work / "deflate", o.brick,
                                           nccopy_cache_args(o.dims.x, o.dims.y, o.brick));
  }

  for (const double fraction : o.fractions) {
    LossyStoreRun run;
    run.fraction = fraction;
    std::vector<build::LossyRequest> lossy;
    for (const auto& [name, range] : report.ranges) {
      const double tolerance = fraction * (range.second - range.first);
      if (tolerance > 0 && std::isfinite(tolerance)) {
        lossy.push_back({name, format::LossyMode::kAbsolute, tolerance});
      }
    }
    const auto dir = o.work / fmt::format("store-lossy-{:g}", fraction);
    spdlog::info("bench: lossy store at {} of each range, {} conversion(s)", fraction, o.repeat);
    timed_conversions(o, report.input, lossy, dir, run);
    run.cold_read_us = cold_reads(o, dir);
    const auto store = Store::open(dir);
    const StoreSizes sizes = measure_store_sizes(dir);
    for (std::size_t i = 0; i < o.variables.size(); ++i) {
      const std::string& name = o.variables[i];
      LossyVariableRow row;
      row.variable = name;
      row.fraction = fraction;
      for (const auto& r : lossy) row.tolerance = r.variable == name ? r.value : row.tolerance;
      const auto* size = sizes.find(name);
      row.store_bytes = size ? size->store_bytes() : 0;
      const auto v = static_cast<std::uint32_t>(store->manifest().variable_index(name));
      const ErrorSums e = level0_error(*exact, *store, v);
      row.max_error = e.max;
      row.rms_error = e.count ? std::sqrt(e.sum2 / static_cast<double>(e.count)) : 0.0;
      row.valid_samples = e.count;
      run.variables.push_back(row);
    }
    if (o.extraction) {
      for (const ExtractCase& c : default_level_cases()) {
        bool have = true;
        for (const CaseLimit& l : c.limits) {
          have = have && std::find(o.variables.begin(), o.variables.end(), l.var) != o.variables.end();
        }
        if (have) run.surfaces.push_back(compare_level0_surfaces(*exact, *store, c));
      }
    }
    report.runs.push_back(std::move(run));
    if (!o.keep) std::filesystem::remove_all(dir);
  }
  if (!o.plot_png.empty()) report.plot_status = write_lossy_plot(report, o.plot_png);
  report.seconds = clock.seconds();
  if (!o.keep) {
    std::error_code ec;
    std::filesystem::remove_all(lossless_dir, ec);
  }
  return report;
}

std::vector<Table> lossy_report_tables(const LossySuiteReport& r) {
  std::vector<Table> tables;
  const LossyStoreRun& base = r.runs.front();
  Table sizes{"lossy_sizes",
              "Store size per variable (step 0): lossy against lossless and NetCDF-4 deflate level 1; "
              "data error at level 0 over valid samples",
              {"variable", "tolerance", "abs tolerance", "MB", "x smaller than lossless",
               "x smaller than deflate", "max error", "max error / tolerance", "RMS error"}, {}, {}};
  for (const LossyStoreRun& run : r.runs) {
    for (std::size_t i = 0; i < run.variables.size(); ++i) {
      const LossyVariableRow& v = run.variables[i];
      const double lossless = base.variables[i].store_bytes;
      const DeflateSize* d = r.deflate.find(v.variable);
      const double deflate = d ? static_cast<double>(d->bytes) : NAN;
      sizes.add({v.variable, fraction_label(run.fraction), Cell(v.tolerance, 6),
                 Cell(v.store_bytes / 1e6, 2), Cell(v.store_bytes > 0 ? lossless / v.store_bytes : NAN, 2),
                 Cell(v.store_bytes > 0 ? deflate / v.store_bytes : NAN, 2), Cell(v.max_error, 6),
                 Cell(v.tolerance > 0 ? v.max_error / v.tolerance : 0.0, 3), Cell(v.rms_error, 6)});
    }
  }
  sizes.notes.push_back("tolerance: a fraction of the variable's range over the step (max - min), "
                        "passed as --lossy VAR=abs:TOL; MB: chunks + index + share of the step "
                        "file's fixed parts (bench/store_sizes.h)");
  tables.push_back(std::move(sizes));

  Table runs{"lossy_runs",
             "Conversion throughput and cold level-0 brick read + decode (all variables)",
             {"tolerance", "convert MB/s", "convert s (median)", "zfp bricks", "fallback bricks",
              "data bricks", "cold read p50 us", "cold read p99 us", "p50 vs lossless"}, {}, {}};
  for (const LossyStoreRun& run : r.runs) {
    runs.add({fraction_label(run.fraction), Cell(run.mb_per_s(), 1), Cell(median(run.convert_seconds), 2),
              Cell::integer(double(run.zfp_bricks)), Cell::integer(double(run.fallback_bricks)),
              Cell::integer(double(run.data_bricks)), Cell(run.cold_read_us.p50, 0),
              Cell(run.cold_read_us.p99, 0),
              Cell(base.cold_read_us.p50 > 0 ? run.cold_read_us.p50 / base.cold_read_us.p50 : NAN, 2)});
  }
  runs.notes.push_back(fmt::format("{} cold reads per store (page cache evicted before each), "
                                   "{} conversion(s) per store from warm input",
                                   r.options.reads, r.options.repeat));
  tables.push_back(std::move(runs));

  Table surfaces{"lossy_extraction",
                 "Level-0 extraction of the scene cases: lossy store against the lossless one",
                 {"case", "tolerance", "volume difference", "distance mean (cells)",
                  "distance p90 (cells)", "distance max (cells)", "triangles", "lossless triangles"}, {}, {}};
  for (const LossyStoreRun& run : r.runs) {
    for (const SurfaceComparison& s : run.surfaces) {
      surfaces.add({s.case_name, fraction_label(run.fraction), Cell(s.volume_error, 6),
                    Cell(s.distance_mean, 4), Cell(s.distance_p90, 4), Cell(s.distance_max, 3),
                    Cell::integer(double(s.triangles)), Cell::integer(double(s.reference_triangles))});
    }
  }
  surfaces.notes.push_back("volume difference: (lossy - lossless) / lossless enclosed volume; "
                           "distances in level-0 cells between the limit surfaces, both ways");
  tables.push_back(std::move(surfaces));
  return tables;
}

nlohmann::json lossy_report_json(const LossySuiteReport& r, const std::vector<Table>& tables) {
  nlohmann::json t = nlohmann::json::array();
  for (const auto& table : tables) t.push_back(table_json(table));
  nlohmann::json ranges = nlohmann::json::object();
  for (const auto& [name, range] : r.ranges) ranges[name] = {range.first, range.second};
  return {{"suite", "lossy"},
          {"command", r.options.command_line},
          {"dims", {r.options.dims.x, r.options.dims.y, r.options.dims.z}},
          {"variables", r.options.variables},
          {"fractions", r.options.fractions},
          {"ranges", ranges},
          {"seconds", r.seconds},
          {"machine", r.machine},
          {"plot", r.plot_status},
          {"tables", t}};
}

}  // namespace strielad::bench
