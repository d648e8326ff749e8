// SPDX-License-Identifier: Apache-2.0
#include "bench/io_suite.h"

#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include "bench/machine_info.h"
#include "bench/process_runner.h"
#include "bench/stopwatch.h"
#include "core/error.h"
#include "synthetic/sample_variables.h"
#include "store/store.h"
#include "vdb/level_grid.h"

namespace strielad::bench {
namespace {

std::string dims_text(Dims3 d) { return fmt::format("{}x{}x{}", d.x, d.y, d.z); }

void check_options(const IoSuiteOptions& o) {
  if (o.dims.x < 2 || o.dims.y < 2 || o.dims.z < 2) {
    throw make_error(ErrorCode::kInvalidArgument, "--dims {}: every axis needs at least 2 samples",
                     dims_text(o.dims));
  }
  if (o.variables.empty()) throw make_error(ErrorCode::kInvalidArgument, "--vars: no variables");
  for (const auto& v : o.variables) synthetic::sample_variable_from_name(v);
  if (o.repeat < 1) throw make_error(ErrorCode::kInvalidArgument, "--repeat must be at least 1");
  if (o.reads < 1) throw make_error(ErrorCode::kInvalidArgument, "--reads must be at least 1");
}

}  // namespace

std::vector<format::CodecSpec> default_sweep_codecs() {
  std::vector<format::CodecSpec> out;
  for (const char* shuffle : {"byte", "bit"}) {
    for (int level : {1, 3, 5}) out.push_back({"zstd", level, shuffle});
    out.push_back({"lz4", 5, shuffle});
  }
  return out;
}

IoSuiteOptions quick_io_options(IoSuiteOptions o) {
  o.dims = {40, 36, 24};
  o.repeat = 1;
  o.reads = 20;
  o.first_brick_reads = 3;
  o.sweep_dims = o.dims;
  o.sweep_bricks = {8, 16};
  o.sweep_codecs = {{"zstd", 5, "byte"}, {"lz4", 5, "bit"}};
  o.sweep_repeat = 1;
  o.sweep_reads = 10;
  o.extra_codecs = {{"lz4", 5, "byte"}};
  return o;
}

namespace {

// The suite's folders below o.work.
struct IoDirs {
  std::filesystem::path input, main, deflate, sweep, sweep_input;
};

IoDirs io_dirs(const IoSuiteOptions& o) {
  const std::string vars = fmt::format("{}", fmt::join(o.variables, "-"));
  return {o.work / fmt::format("input-{}-{}", dims_text(o.dims), vars), o.work / "main",
          o.work / "deflate", o.work / "sweep",
          o.work / fmt::format("input-{}-{}", dims_text(o.sweep_dims), vars)};
}

ConversionBenchOptions conversion_options(const IoSuiteOptions& o, const IoSuiteReport& report,
                                          const std::filesystem::path& work, bool have_nccopy,
                                          const std::vector<std::string>& nccopy_extra) {
  ConversionBenchOptions co;
  co.inputs = report.input.files;
  co.variables = o.variables;
  co.work = work;
  co.brick = o.brick;
  co.codec = o.codec;
  co.fpzip = o.fpzip;
  co.threads = o.threads;
  co.repeat = o.repeat;
  co.with_nccopy = have_nccopy;
  co.nccopy_extra = nccopy_extra;
  // With fpzip, the main codec without it runs too: the same run compares them.
  for (const auto& c : o.extra_codecs) {
    if (!(c == o.codec) || !o.fpzip.empty()) co.extra_codecs.push_back(c);
  }
  return co;
}

// Level 0 of every variable of the converted store as one .vdb file each, for the
// delayed-loading reads.
std::vector<std::filesystem::path> write_vdb_files(const std::filesystem::path& store_dir,
                                                   const std::filesystem::path& vdb_dir) {
  spdlog::info("bench: writing level 0 of every variable as .vdb for the delayed-loading reads");
  const auto store = Store::open(store_dir);
  std::filesystem::create_directories(vdb_dir);
  std::vector<std::filesystem::path> files;
  for (std::uint32_t v = 0; v < store->variable_count(); ++v) {
    const auto path = vdb_dir / (store->manifest().variables[v].name + ".vdb");
    vdb::write_level_vdb(*store, 0, v, 0, path);
    files.push_back(path);
  }
  return files;
}

BrickReadBench run_reads(const IoSuiteOptions& o, const IoSuiteReport& report, bool have_nccopy) {
  spdlog::info("bench: random brick reads ({} per set)", o.reads);
  BrickReadOptions ro;
  ro.store = report.conversion.store;
  if (have_nccopy) ro.netcdf = report.conversion.nccopy_output;
  ro.variables = o.variables;
  ro.reads = o.reads;
  ro.first_brick_reads = o.first_brick_reads;
  ro.seed = o.read_seed;
  ro.scratch = o.work;
  if (o.vdb_reads) ro.vdb_files = write_vdb_files(report.conversion.store, o.work / "vdb");
  return run_brick_read_bench(ro);
}

// The brick-size and codec sweeps on their own (usually smaller) input.
void run_sweeps(const IoSuiteOptions& o, const IoDirs& dirs, IoSuiteReport& report) {
  report.sweep_input = o.sweep_dims == o.dims
                           ? report.input
                           : ensure_sample_input({o.sweep_dims, 1, o.variables, o.seed},
                                                 dirs.sweep_input);
  SweepOptions so;
  so.inputs = report.sweep_input.files;
  so.variables = o.variables;
  so.work = dirs.sweep;
  so.repeat = o.sweep_repeat > 0 ? o.sweep_repeat : o.repeat;
  so.reads = o.sweep_reads;
  so.threads = o.threads;
  so.seed = o.read_seed;
  std::filesystem::create_directories(dirs.sweep);
  std::vector<SweepConfig> bricks, codecs;
  for (std::uint32_t b : o.sweep_bricks) bricks.push_back({fmt::format("B={}", b), b, o.codec});
  for (const auto& c : o.sweep_codecs) codecs.push_back({codec_label(c), o.brick, c});
  spdlog::info("bench: brick-size sweep on {} ({} configurations)", dims_text(o.sweep_dims),
               bricks.size());
  report.brick_sweep = run_sweep(so, bricks);
  spdlog::info("bench: codec sweep on {} ({} configurations)", dims_text(o.sweep_dims),
               codecs.size());
  report.codec_sweep = run_sweep(so, codecs);
}

}  // namespace

IoSuiteReport run_io_suite(const IoSuiteOptions& options) {
  check_options(options);
  const Stopwatch clock;
  IoSuiteReport report;
  report.options = options;
  if (report.options.sweep_codecs.empty()) report.options.sweep_codecs = default_sweep_codecs();
  const IoSuiteOptions& o = report.options;
  std::filesystem::create_directories(o.work);
  report.machine = machine_info(o.work);
  const IoDirs dirs = io_dirs(o);

  const bool have_nccopy = o.nccopy && find_program("nccopy").has_value();
  if (o.nccopy && !have_nccopy) spdlog::warn("bench: nccopy not found on PATH; skipping NetCDF competitors");

  report.input = ensure_sample_input({o.dims, 1, o.variables, o.seed}, dirs.input);
  std::vector<std::string> nccopy_extra;
  if (o.nccopy_tuned_cache) nccopy_extra = nccopy_cache_args(o.dims.x, o.dims.y, o.brick);
  nccopy_extra.insert(nccopy_extra.end(), o.nccopy_extra.begin(), o.nccopy_extra.end());

  spdlog::info("bench: conversion throughput, {} round(s)", o.repeat);
  report.conversion =
      run_conversion_bench(conversion_options(o, report, dirs.main, have_nccopy, nccopy_extra));

  spdlog::info("bench: store sizes");
  report.sizes = measure_store_sizes(report.conversion.store);
  if (have_nccopy) {
    report.nccopy_total_bytes = std::filesystem::file_size(report.conversion.nccopy_output);
    spdlog::info("bench: NetCDF-4 deflate size per variable (nccopy -V)");
    report.deflate = measure_deflate_sizes(report.input.files.front(), o.variables, dirs.deflate,
                                           o.brick, nccopy_extra);
  }
  report.reads = run_reads(o, report, have_nccopy);
  if (o.sweeps) run_sweeps(o, dirs, report);

  report.targets = evaluate_io_targets(report);
  report.seconds = clock.seconds();
  report.machine["load_average_1min_end"] = load_average_1min();
  if (!o.keep) {
    std::error_code ec;
    for (const auto& dir : {dirs.main, dirs.deflate, dirs.sweep, dirs.input, dirs.sweep_input}) {
      std::filesystem::remove_all(dir, ec);
    }
  }
  return report;
}

}  // namespace strielad::bench
