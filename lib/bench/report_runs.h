// SPDX-License-Identifier: Apache-2.0
// What a benchmark report ran, kept as OUT/runs.json next to its BENCHMARKS.md: every
// suite's command, exit status, time and files, and the noise probes. `strielad-bench
// report --rerun SUITES` reads it back, runs only the named suites again and writes the
// whole report from the new runs and the kept ones. Its paths are written as
// bench/report_paths.h writes them (relative to the repository, $WORK, $OUT, ...) and
// resolved again on reading.
#pragma once

#include <filesystem>

#include "bench/benchmark_report.h"
#include "bench/report_paths.h"

namespace strielad::bench {

// \error kIo when the file cannot be written (written atomically).
void save_report_runs(const ReportInput& input, const std::filesystem::path& file,
                      const ReportPaths& paths);

// \error kNotFound when the file is missing; kInvalidInput naming the file and the field
// when it is not a runs file.
ReportInput load_report_runs(const std::filesystem::path& file, const ReportPaths& paths);

}  // namespace strielad::bench
