// SPDX-License-Identifier: Apache-2.0
// The `strielad-bench robustness` suite ("Stability on stiff and
// extreme cases"): runs the robustness matrix (robust/extreme_cases.h) through conversion,
// verification, statistics, coarse levels, extraction, the server and advection, and
// reports each stage's outcome against the expected one (docs/robustness.md).
#pragma once

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "bench/table_writer.h"
#include "robust/case_runner.h"

namespace strielad::bench {

struct RobustnessSuiteOptions {
  std::vector<std::string> cases;  // names; empty = every case (quick: a few)
  std::filesystem::path work_dir;  // empty: a fresh folder under the system temp dir
  int threads = 2;
  bool keep = false;   // keep each case's input and store
  bool quick = false;  // a handful of cases: checks the harness
  std::string command_line;
};

struct RobustnessSuiteReport {
  RobustnessSuiteOptions options;
  std::vector<robust::CaseReport> cases;
  nlohmann::json machine;
  double seconds = 0;
  std::size_t deviating() const;
};

// The cases quick mode runs.
std::vector<std::string> quick_robustness_cases();

// \error kNotFound for an unknown case name.
RobustnessSuiteReport run_robustness_suite(const RobustnessSuiteOptions& options);
std::vector<Table> robustness_report_tables(const RobustnessSuiteReport& report);
nlohmann::json robustness_report_json(const RobustnessSuiteReport& report,
                                      const std::vector<Table>& tables);

}  // namespace strielad::bench
