// SPDX-License-Identifier: Apache-2.0
// The `strielad-bench lossy` suite: what error-bounded lossy bricks (strielad-convert
// --lossy, zfp) buy and cost on one generated time step. For a sweep of tolerances, each a
// fraction of a variable's range, on a dense field (temperature, wind) and a sparse one
// (cloud water): the store's size against the lossless store and NetCDF-4 deflate; cold
// brick read + decode time (p50, p99) against lossless; the error reached (max, RMS over
// the valid level-0 samples) against the tolerance and the fallback bricks; the scene
// cases' level-0 extraction against the lossless store's (enclosed-volume difference,
// surface distance); conversion throughput. Tests call run_lossy_suite with quick options.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/deflate_sizes.h"
#include "bench/extract_levels.h"
#include "bench/latency_stats.h"
#include "bench/sample_input.h"
#include "bench/table_writer.h"
#include "convert/converter.h"

namespace strielad::bench {

struct LossySuiteOptions {
  Dims3 dims{1429, 1556, 150};  // one full time step of the paper's grid, as the io suite
  std::vector<std::string> variables{"ta", "ua", "clw"};
  // Tolerances as fractions of each variable's range (max - min over the step), converted
  // to absolute ones (--lossy VAR=abs:TOL) so that conversion is timed without the range
  // pass a rel: request costs.
  std::vector<double> fractions{1e-4, 1e-3, 1e-2};
  std::filesystem::path work = "/tmp/strielad-bench-lossy";
  int repeat = 3;              // conversions per store (medians)
  std::size_t reads = 300;     // cold brick reads per store
  std::uint32_t brick = build::kDefaultBrick;
  int threads = 0;
  std::uint64_t seed = 1;
  bool nccopy = true;          // NetCDF-4 deflate sizes (nccopy)
  bool extraction = true;      // the scene cases at level 0
  bool keep = false;
  bool quick = false;
  std::filesystem::path plot_png;  // empty: no chart
  std::string command_line;
};

// Tiny grid, two tolerances, one round, few reads: seconds, for CI.
LossySuiteOptions quick_lossy_options(LossySuiteOptions base);

struct LossyVariableRow {
  std::string variable;
  double fraction = 0;     // 0: the lossless store
  double tolerance = 0;    // absolute (0: lossless)
  double store_bytes = 0;  // the variable's share of step 0 (bench/store_sizes.h)
  double max_error = 0, rms_error = 0;  // over valid level-0 samples
  std::uint64_t valid_samples = 0;
};

struct LossyStoreRun {
  double fraction = 0;  // 0: lossless
  std::vector<double> convert_seconds;
  std::uint64_t input_bytes = 0;
  std::uint64_t zfp_bricks = 0, fallback_bricks = 0, data_bricks = 0;
  Summary cold_read_us;  // "store cold, level 0"
  std::vector<LossyVariableRow> variables;
  std::vector<SurfaceComparison> surfaces;  // empty for lossless
  double mb_per_s() const;
};

struct LossySuiteReport {
  LossySuiteOptions options;
  nlohmann::json machine;
  SampleInput input;
  std::vector<std::pair<std::string, std::pair<double, double>>> ranges;  // variable -> min, max
  DeflateSizes deflate;
  std::vector<LossyStoreRun> runs;  // lossless first
  std::string plot_status;
  double seconds = 0;
};

LossySuiteReport run_lossy_suite(const LossySuiteOptions& options);

std::vector<Table> lossy_report_tables(const LossySuiteReport& report);
nlohmann::json lossy_report_json(const LossySuiteReport& report, const std::vector<Table>& tables);

// gnuplot script, data and PNG next to `png`; returns run_gnuplot's status.
std::string write_lossy_plot(const LossySuiteReport& report, const std::filesystem::path& png);

}  // namespace strielad::bench
