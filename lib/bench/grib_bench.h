// SPDX-License-Identifier: Apache-2.0
// GRIB conversion side by side, on one generated sample (lib/synthetic) written both as
// GRIB2 (16-bit simple packing, hybrid level numbers: grib_to_netcdf collapses
// heightAboveSea levels, which MARS files under levtype sfc without a level) and as
// CF-NetCDF-4 float32:
//   A  strielad-convert of the GRIB2 file (in process);
//   B  grib_to_netcdf -D NC_FLOAT (a child process) then strielad-convert of its output,
//      timed apart and summed (the NetCDF file in between is read as it was left, as a
//      user's pipeline would);
//   C  strielad-convert of the NetCDF sample (the reference).
// The contenders take turns in every round, each starting with its input evicted from the
// page cache; the A and B stores are compared sample by sample at level 0.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "bench/conversion_bench.h"
#include "bench/table_writer.h"
#include "grid/axis.h"

namespace strielad::bench {

struct GribBenchOptions {
  Dims3 dims{715, 778, 75};
  int repeat = 3;
  std::filesystem::path work = "/tmp/strielad-bench-grib";
  std::uint32_t brick = 24;
  int threads = 0;  // converter threads, 0 = all cores
  int grib_bits = 16;
  std::string command_line;
};

// A tiny grid (48x40x10), one round: checks the harness.
GribBenchOptions quick_grib_options(GribBenchOptions o);

// Level 0 of two stores, variable by variable (names mapped), sample by sample.
struct StoreDifference {
  std::size_t variables = 0;
  std::uint64_t samples = 0;
  std::uint64_t missing_mismatches = 0;  // missing in one store only
  double max_abs_difference = 0;
  double max_relative_difference = 0;    // against the variable's range at its level
  std::string problem;                   // why nothing could be compared; empty when fine
  bool equal() const {
    return problem.empty() && missing_mismatches == 0 && max_abs_difference == 0;
  }
};

// `name_in_b` maps a variable name of `a` to its name in `b`. x and y are matched by value
// (1e-4 degrees: grib_to_netcdf writes float32 coordinates), z by value when both stores
// have the same level values, else by index. Throws what reading a store throws.
StoreDifference compare_stores_level0(const std::filesystem::path& a,
                                      const std::filesystem::path& b,
                                      const std::function<std::string(const std::string&)>&
                                          name_in_b);

struct GribBenchReport {
  GribBenchOptions options;
  // A, B: grib_to_netcdf, B: strielad-convert, B total, C
  std::vector<ContenderRuns> contenders;
  std::uint64_t grib_bytes = 0, netcdf_bytes = 0, b_netcdf_bytes = 0;
  std::uint64_t samples = 0;  // of all variables, one step
  double generate_seconds = 0;
  bool reused_input = false;
  std::string grib_to_netcdf;  // its path; empty when not found (B skipped)
  std::string b_failure;       // why B stopped; empty when it ran
  StoreDifference a_vs_b, a_vs_c;
  double seconds = 0;
};

GribBenchReport run_grib_bench(const GribBenchOptions& options);
std::vector<Table> grib_tables(const GribBenchReport& report);
nlohmann::json grib_json(const GribBenchReport& report, const std::vector<Table>& tables);

}  // namespace strielad::bench
