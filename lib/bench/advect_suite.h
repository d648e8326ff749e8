// SPDX-License-Identifier: Apache-2.0
// The `strielad-bench advect` suite (issue 6, "Error against run time"): every
// integrator of lib/advect at several step sizes or tolerances on wind fields sampled
// onto grids whose trajectories are known: solid-body rotation, a shear layer with
// rising air, stiff convergence towards a fixed line (stiffness ratios 10^3 and 10^4),
// and a time-dependent field of vortices against a very fine RK4 reference. Reports the
// error at the end time against wall time and against the number of field evaluations.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "bench/table_writer.h"

namespace strielad::bench {

struct AdvectSuiteOptions {
  int repeat = 5;       // timed runs per setting (the median is reported)
  int trajectories = 16;  // start points per flow, spread over the domain
  bool quick = false;   // fewer settings, 2 start points, 1 repeat: checks the harness
  std::string command_line;
};

struct AdvectRun {
  std::string flow;
  std::string method;    // euler, rk4, dopri5
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
  std::vector<AdvectRun> runs;
  nlohmann::json machine;
  double seconds = 0;
};

AdvectSuiteReport run_advect_suite(const AdvectSuiteOptions& options);
std::vector<Table> advect_report_tables(const AdvectSuiteReport& report);
nlohmann::json advect_report_json(const AdvectSuiteReport& report, const std::vector<Table>& tables);

}  // namespace strielad::bench
