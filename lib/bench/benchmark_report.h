// SPDX-License-Identifier: Apache-2.0
// The one reproducible performance report (strielad-bench report): the suites'
// JSON reports, gathered after each ran as its own process, become one Markdown file
// with the machine, every suite's command, status and tables, and the charts: throughput
// against peers, the cut's arrival curves, error against run time, scene economy.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "bench/report_paths.h"

namespace strielad::bench {

struct SuiteRun {
  std::string suite;                // "io", "extract", ...
  std::vector<std::string> argv;    // as run
  int exit_status = -1;
  double seconds = 0;
  std::filesystem::path json, csv, log;  // what it wrote; log = its stdout and stderr
  std::filesystem::path plot;      // the suite's own chart (--plot), if asked for
  std::string output_tail;          // of a failed run
};

// One noise probe (bench/noise_probe.h) taken between suites.
struct NoiseProbe {
  std::string when;  // "before io", "after robustness", ...
  double seconds = 0;
};

struct ReportInput {
  std::vector<SuiteRun> runs;
  std::vector<NoiseProbe> probes;
  std::string command_line;  // the report's own command
  std::vector<std::string> notes;  // e.g. which suites a later --rerun ran again
  std::string mode;          // "quick" or the stated size
  std::filesystem::path out; // folder of the report, its charts and the suites' files
};

struct ReportOutput {
  std::filesystem::path markdown;
  std::vector<std::filesystem::path> charts;  // written
  std::vector<std::string> chart_problems;    // "chart: why not"
};

// Reads every run's JSON (a missing or unreadable one is reported in the Markdown, not
// thrown), draws the charts and writes OUT/BENCHMARKS.md with its paths as `paths`
// writes them. \error kIo when the Markdown cannot be written.
ReportOutput write_benchmark_report(const ReportInput& input, const ReportPaths& paths);

}  // namespace strielad::bench
