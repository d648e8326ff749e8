// SPDX-License-Identifier: Apache-2.0
// What terrain-following levels cost (`strielad-bench geometry`), on generated samples of
// one grid size (lib/synthetic): the rectilinear sample on height levels, the ICON-like
// sample (z_ifc half levels: a time-invariant height field) and the hybrid sigma-pressure
// sample (a pressure field per step).
//   conversion: strielad-convert of each, taking turns, inputs evicted from the page
//     cache: seconds, million samples per second, store bytes per sample, the geometry's
//     bytes;
//   extraction (after a warm-up run of each, the stores in the page cache): every level-0
//     node of a dense surface (temperature <= 260 K) on one thread, each store in the axis frame (no geometry read) and placed in the lonlat
//     frame (the geometry field read, carried and applied; on the rectilinear sample the
//     height axis places it): the placed time against the axis time is the cost of the
//     geometry map (target: at most 1.3x).
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/table_writer.h"
#include "grid/axis.h"

namespace strielad::bench {

struct GeometryBenchOptions {
  Dims3 dims{286, 312, 60};
  std::size_t steps = 2;
  int repeat = 3;
  std::filesystem::path work = "/tmp/strielad-bench-geometry";
  std::uint32_t brick = 24;
  int threads = 0;  // converter threads, 0 = all cores (extraction runs on one)
  std::string command_line;
};

// A tiny grid (40x36x16), one round: checks the harness.
GeometryBenchOptions quick_geometry_options(GeometryBenchOptions o);

struct GeometryInputRuns {
  std::string name;       // "rectilinear", "icon", "sigma-pressure"
  std::string geometry;   // what places the levels
  std::uint64_t samples = 0;       // all variables, all steps
  std::uint64_t input_bytes = 0;
  std::uint64_t store_bytes = 0;   // the whole store directory
  std::uint64_t geometry_bytes = 0;  // geometry.bricks, GEOMETRY and sections of step files
  std::vector<double> convert_seconds;
  // Extraction of level 0 per round: axis frame with node-face squares merged (the axis
  // frame's default) and without (as frames that bend the lattice extract), and placed.
  std::vector<double> axis_seconds, unmerged_seconds, placed_seconds;
  // The same runs' CPU seconds (user + system): steadier than wall time on a shared machine.
  std::vector<double> unmerged_cpu_seconds, placed_cpu_seconds;
  // Placed with the geometry bricks already in a kept brick cache (read for another
  // step first), the data bricks cold: a server stepping through time with a
  // time-invariant geometry field. Empty when the geometry has no bricks shared by the
  // steps (a per-step field, or none).
  std::vector<double> placed_warm_seconds, placed_warm_cpu_seconds;
  std::uint64_t nodes = 0, triangles_axis = 0, triangles_unmerged = 0, triangles_placed = 0;
  std::uint64_t bricks_axis = 0, bricks_placed = 0;
};

struct GeometryBenchReport {
  GeometryBenchOptions options;
  std::vector<GeometryInputRuns> inputs;
  double seconds = 0;
};

GeometryBenchReport run_geometry_bench(const GeometryBenchOptions& options);
std::vector<Table> geometry_tables(const GeometryBenchReport& report);
nlohmann::json geometry_json(const GeometryBenchReport& report, const std::vector<Table>& tables);

}  // namespace strielad::bench
