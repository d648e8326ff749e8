// SPDX-License-Identifier: Apache-2.0
// The `strielad-bench advect` suite ("Error against run time"): every
// integrator of lib/advect (Euler, RK4, Dormand-Prince 5(4), Rosenbrock RODAS3) at
// several step sizes or tolerances on wind fields sampled onto grids whose trajectories
// are known: solid-body rotation, a shear layer with rising air, stiff convergence
// towards a fixed line (stiffness ratios 10^3 and 10^4); and, against a very fine RK4
// reference, a time-dependent field of vortices and the wind of the sample-data generator
// (lib/synthetic, the ua/va/wa that `strielad-sample` writes) at two output times
// on its lon/lat/height grid. Reports the error at the end time against wall time and
// against the number of field evaluations, and can draw the work-precision diagrams.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/table_writer.h"

namespace strielad::bench {

struct AdvectSuiteOptions {
  int repeat = 5;       // timed runs per setting (the median is reported)
  int trajectories = 16;  // start points per flow, spread over the domain
  bool quick = false;   // fewer settings, 2 start points, 1 repeat, small generated grid
  // The work-precision diagrams (PNG via gnuplot, with its .gp and .dat next to it);
  // empty = none. Without gnuplot on PATH the script is written, with a warning.
  std::filesystem::path plot_png;
  std::string command_line;
};

struct AdvectFlowInfo {
  std::string name;
  int trajectories = 0;  // start points measured
  std::string note;      // e.g. start points whose reference left the domain; may be empty
};

struct AdvectRun {
  std::string flow;
  std::string method;    // euler, rk4, dopri5, rosenbrock
  std::string setting;   // "step 60 s" or "rtol 1e-06"
  double max_error_m = 0;       // over the start points; NaN when some did not reach the end
  double median_error_m = 0;
  double wall_us = 0;           // median over repeats, all start points together
  std::uint64_t evaluations = 0;  // all start points together
  int reached = 0, trajectories = 0;
  std::string stops;             // e.g. "16 reached" or "12 left the domain, 4 reached"
};

struct AdvectSuiteReport {
  AdvectSuiteOptions options;
  std::vector<AdvectFlowInfo> flows;
  std::vector<AdvectRun> runs;  // flow by flow, in the order of `flows`
  nlohmann::json machine;
  std::string plot_status;  // "written", or why not; empty without plot_png
  double seconds = 0;
};

// \error kIo when the plot's files cannot be written (a missing gnuplot is no error).
AdvectSuiteReport run_advect_suite(const AdvectSuiteOptions& options);
std::vector<Table> advect_report_tables(const AdvectSuiteReport& report);
nlohmann::json advect_report_json(const AdvectSuiteReport& report, const std::vector<Table>& tables);

// Writes the work-precision diagrams' data and gnuplot script next to `png` (same stem,
// .dat and .gp): one panel per flow, max error against field evaluations and against
// wall time, and runs gnuplot when it is on PATH. Returns "written" or why the PNG was
// not made (the script is written regardless). \error kIo from writing the files.
std::string write_advect_plot(const AdvectSuiteReport& report,
                              const std::filesystem::path& png);

}  // namespace strielad::bench
