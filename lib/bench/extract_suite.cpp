// SPDX-License-Identifier: Apache-2.0
#include "bench/extract_suite.h"

#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <algorithm>

#include "bench/machine_info.h"
#include "bench/stopwatch.h"
#include "convert/converter.h"
#include "core/error.h"
#include "synthetic/sample_variables.h"
#include "store/store.h"

namespace strielad::bench {
namespace {

std::string dims_text(Dims3 d) { return fmt::format("{}x{}x{}", d.x, d.y, d.z); }

void check_options(const ExtractSuiteOptions& o) {
  if (o.dims.x < 2 || o.dims.y < 2 || o.dims.z < 2) {
    throw make_error(ErrorCode::kInvalidArgument, "--dims {}: every axis needs at least 2 samples",
                     dims_text(o.dims));
  }
  for (const auto& v : o.variables) synthetic::sample_variable_from_name(v);
  if (o.repeat < 1) throw make_error(ErrorCode::kInvalidArgument, "--repeat must be at least 1");
  if (o.level_repeat < 1) {
    throw make_error(ErrorCode::kInvalidArgument, "--level-repeat must be at least 1");
  }
  if (o.bricks.empty() && o.levels == false) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "nothing to measure: no brick size and no levels");
  }
  for (std::uint32_t b : o.bricks) {
    if (b < 2) throw make_error(ErrorCode::kInvalidArgument, "--brick-sizes: {} is below 2", b);
  }
  for (const auto* cases : {&o.cases, &o.level_cases}) {
    for (const ExtractCase& c : *cases) {
      if (c.limits.empty() || c.select >= c.limits.size()) {
        throw make_error(ErrorCode::kInvalidArgument, "case {}: no limit to select bricks by",
                         c.name);
      }
      for (const CaseLimit& l : c.limits) {
        if (std::find(o.variables.begin(), o.variables.end(), l.var) == o.variables.end()) {
          throw make_error(ErrorCode::kInvalidArgument,
                           "case {} needs variable {}, which --vars does not generate ({})", c.name,
                           l.var, fmt::join(o.variables, ","));
        }
      }
    }
  }
}

}  // namespace

ExtractSuiteOptions quick_extract_options(ExtractSuiteOptions o) {
  o.dims = {52, 48, 40};
  o.bricks = {8, 12};
  o.bricks_per_case = 3;
  o.repeat = 2;
  o.level_brick = 8;
  o.level_repeat = 1;
  return o;
}

ExtractSuiteReport run_extract_suite(const ExtractSuiteOptions& options) {
  check_options(options);
  const Stopwatch clock;
  ExtractSuiteReport report;
  report.options = options;
  const ExtractSuiteOptions& o = report.options;
  std::filesystem::create_directories(o.work);
  report.machine = machine_info(o.work);
  report.machine["vtk"] = peer_versions().at("vtk");
  report.machine["openvdb"] = peer_versions().at("openvdb");
  const std::string vars = fmt::format("{}", fmt::join(o.variables, "-"));
  const auto input_dir = o.work / fmt::format("input-{}-{}", dims_text(o.dims), vars);
  report.input = ensure_sample_input({o.dims, 1, o.variables, o.seed}, input_dir);

  // One store per brick size (and the level store), in the order asked.
  std::vector<std::uint32_t> sizes = o.bricks;
  if (o.levels && std::find(sizes.begin(), sizes.end(), o.level_brick) == sizes.end()) {
    sizes.push_back(o.level_brick);
  }
  std::vector<std::filesystem::path> store_dirs;
  {
    const Stopwatch convert_clock;
    for (std::uint32_t b : sizes) {
      store_dirs.push_back(o.work / fmt::format("store-b{}", b));
      spdlog::info("bench: converting into {} (brick {})", store_dirs.back().string(), b);
      convert_sample_store(report.input, o.variables, b, o.threads, store_dirs.back());
    }
    report.convert_seconds = convert_clock.seconds();
  }
  auto store_for = [&](std::uint32_t b) {
    const auto it = std::find(sizes.begin(), sizes.end(), b);
    return Store::open(store_dirs[static_cast<std::size_t>(it - sizes.begin())]);
  };

  BrickGroupOptions bo;
  bo.bricks = o.bricks_per_case;
  bo.repeat = o.repeat;
  bo.seed = o.pick_seed;
  bo.openvdb = o.openvdb;
  for (const ExtractCase& c : o.cases) {
    for (std::uint32_t b : o.bricks) {
      const auto store = store_for(b);
      report.groups.push_back(run_brick_group(*store, c, bo));
    }
  }

  if (o.levels) {
    const auto store = store_for(o.level_brick);
    LevelGroupOptions lo;
    lo.threads = o.threads;
    lo.repeat = o.level_repeat;
    for (const ExtractCase& c : o.level_cases) {
      spdlog::info("bench: error against run time, {} ({}), brick {}, {} level(s)", c.name, c.label,
                   o.level_brick, store->octree().level_count());
      report.level_groups.push_back(run_level_group(*store, c, lo));
      if (o.whole_level_openvdb) {
        if (auto w = run_whole_level_vdb(*store, c, 0, o.level_repeat)) {
          const LevelRow& l0 = report.level_groups.back().rows.front();
          w->kernel_volume = l0.volume;
          w->kernel_seconds_one = l0.median_one();
          report.whole_level.push_back(std::move(*w));
        }
      }
    }
  }

  report.targets = evaluate_extract_targets(report);
  if (!o.plot_png.empty() && !report.level_groups.empty()) {
    report.plot_status = write_extract_level_plot(report, o.plot_png);
  }
  report.seconds = clock.seconds();
  report.machine["load_average_1min_end"] = load_average_1min();
  if (!o.keep) {
    std::error_code ec;
    for (const auto& dir : store_dirs) std::filesystem::remove_all(dir, ec);
    std::filesystem::remove_all(input_dir, ec);
  }
  return report;
}

}  // namespace strielad::bench
