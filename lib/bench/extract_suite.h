// SPDX-License-Identifier: Apache-2.0
// The `strielad-bench extract` suite: on a
// generated sample dataset converted into stores of several brick sizes it compares, on
// the same level-0 bricks, this project's extraction kernel with the paper's VTK clip
// pipeline, vtkFlyingEdges3D and OpenVDB's volumeToMesh (one thread each), and measures
// "error against run time" over the octree levels of the default-brick store. The tool
// (cmd/strielad-bench/extract_command.cpp) is a thin wrapper; the quick test calls
// run_extract_suite with quick options.
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bench/extract_bricks.h"
#include "bench/extract_levels.h"
#include "bench/io_suite.h"
#include "bench/sample_input.h"
#include "bench/table_writer.h"
#include "grid/axis.h"

namespace strielad::bench {

struct ExtractSuiteOptions {
  // 0.4 of the paper's grid along lon and lat, all 150 levels (16% of its samples).
  Dims3 dims{572, 624, 150};
  std::vector<std::string> variables{"clw", "qr", "ta", "ua"};
  std::filesystem::path work = "/tmp/strielad-bench-extract";
  bool keep = false;             // keep the generated input and the stores
  std::uint64_t seed = 1;        // of the sample data
  std::uint64_t pick_seed = 42;  // of the brick choice
  int threads = 0;               // converter and multi-threaded level runs; 0 = all cores

  // Per-brick comparison: brick sizes (stores), cases, bricks per (case, size), rounds.
  std::vector<std::uint32_t> bricks{20, 32, build::kDefaultBrick};
  std::vector<ExtractCase> cases = default_brick_cases();
  std::size_t bricks_per_case = 200;
  int repeat = 5;
  bool openvdb = true;  // OpenVDB volumeToMesh as a contender on one-limit cases

  // Error against run time over the levels of the `level_brick` store.
  bool levels = true;
  std::uint32_t level_brick = build::kDefaultBrick;
  std::vector<ExtractCase> level_cases = default_level_cases();
  int level_repeat = 3;
  bool whole_level_openvdb = true;  // OpenVDB on the whole level-0 grid, sparse cases

  // The plot (error against run time); empty = none. Needs gnuplot on PATH (skipped with
  // a warning otherwise).
  std::filesystem::path plot_png;
  std::string command_line;  // how the suite was invoked, for the report
};

// Tiny grid, a few bricks, two rounds: seconds, for CI.
ExtractSuiteOptions quick_extract_options(ExtractSuiteOptions base);

struct ExtractSuiteReport {
  ExtractSuiteOptions options;
  nlohmann::json machine;
  SampleInput input;
  double convert_seconds = 0;
  std::vector<BrickGroup> groups;        // per case, then per brick size
  std::vector<LevelGroup> level_groups;  // per level case
  std::vector<WholeLevelVdb> whole_level;
  std::vector<Target> targets;
  std::string plot_status;  // "written", or why not
  double seconds = 0;       // whole suite
};

// \error as the generator, the converter and the store (kIo, kInvalidArgument, ...);
// kInvalidArgument for bad options (a brick size < 2, no case, repeat < 1).
ExtractSuiteReport run_extract_suite(const ExtractSuiteOptions& options);

std::vector<Target> evaluate_extract_targets(const ExtractSuiteReport& report);

std::vector<Table> extract_report_tables(const ExtractSuiteReport& report);
nlohmann::json extract_report_json(const ExtractSuiteReport& report,
                                   const std::vector<Table>& tables);

// {"vtk": "9.1.0", "openvdb": "10.0.1"}: the libraries the peers come from.
nlohmann::json peer_versions();

// Writes the gnuplot script and data for the error-against-run-time plot next to
// `png` (same stem, .gp and .dat) and runs gnuplot when it is on PATH. Returns
// "written" or the reason the PNG was not made (the script is written regardless).
std::string write_extract_level_plot(const ExtractSuiteReport& report,
                                     const std::filesystem::path& png);

}  // namespace strielad::bench
