// SPDX-License-Identifier: Apache-2.0
// Runs one robustness case through every stage: writes its NetCDF input, converts it
// (lib/convert), verifies the store, checks the statistics and coarse levels against the
// reference, extracts, asks an in-process server, advects. Every stage ends ok, with a
// clear error, or FAILED (a check failed, kInternal, a foreign exception, bad_alloc);
// nothing a stage throws escapes. Then compares each outcome with the case's expectation.
#pragma once

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "robust/extreme_case.h"

namespace strielad::robust {

struct StageResult {
  Stage stage = Stage::kConvert;
  Outcome outcome = Outcome::kNotRun;
  std::string detail;  // the summary, the error message, or the problems found
  double seconds = 0;
  Expectation expected;
  bool as_expected = false;
};

struct CaseReport {
  std::string name, extreme, expected_text;
  std::vector<StageResult> stages;  // one per Stage, in order
  double seconds = 0;

  bool as_expected() const;
  // "extract: expected ok, got FAILED: ..." per deviating stage.
  std::vector<std::string> deviations() const;
};

struct RunOptions {
  std::filesystem::path work_dir;  // the case runs in work_dir / name (replaced)
  int threads = 2;                 // converter, extraction and server threads
  bool keep_files = false;         // leave the input and the store behind
  std::chrono::milliseconds server_timeout{30000};
};

CaseReport run_case(const ExtremeCase& c, const RunOptions& options);

}  // namespace strielad::robust
