// SPDX-License-Identifier: Apache-2.0
#include "bench/robustness_suite.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <chrono>

#include "bench/machine_info.h"
#include "robust/extreme_cases.h"

namespace strielad::bench {
namespace {

using Clock = std::chrono::steady_clock;

std::string short_outcome(const robust::StageResult& s) {
  switch (s.outcome) {
    case robust::Outcome::kOk: return "ok";
    case robust::Outcome::kClearError: return "error";
    case robust::Outcome::kFailed: return "FAILED";
    case robust::Outcome::kNotRun: return "-";
  }
  return "?";
}

std::string expected_text(const robust::Expectation& e) {
  std::string text(robust::outcome_name(e.outcome));
  if (!e.message_part.empty()) text += fmt::format(" (\"{}\")", e.message_part);
  return text;
}

}  // namespace

std::size_t RobustnessSuiteReport::deviating() const {
  std::size_t n = 0;
  for (const auto& c : cases) n += c.as_expected() ? 0 : 1;
  return n;
}

std::vector<std::string> quick_robustness_cases() {
  return {"baseline", "tiny-and-huge", "nan-inf-refused", "descending-axes", "2^31-cells"};
}

RobustnessSuiteReport run_robustness_suite(const RobustnessSuiteOptions& options) {
  const auto started = Clock::now();
  RobustnessSuiteReport report;
  report.options = options;
  std::vector<std::string> names = options.cases;
  if (names.empty() && options.quick) names = quick_robustness_cases();
  std::vector<robust::ExtremeCase> cases;
  if (names.empty()) {
    cases = robust::extreme_cases();
  } else {
    for (const auto& name : names) cases.push_back(robust::extreme_case(name));
  }
  robust::RunOptions run;
  run.threads = options.threads;
  run.keep_files = options.keep;
  run.work_dir = options.work_dir.empty()
                     ? std::filesystem::temp_directory_path() /
                           fmt::format("strielad-robustness-{}", ::getpid())
                     : options.work_dir;
  std::filesystem::create_directories(run.work_dir);
  // The library's info lines (conversion, server) of every case would bury the tables.
  struct QuietLogs {
    spdlog::level::level_enum was = spdlog::get_level();
    QuietLogs() {
      if (was == spdlog::level::info) spdlog::set_level(spdlog::level::warn);
    }
    ~QuietLogs() { spdlog::set_level(was); }
  };
  for (const auto& c : cases) {
    const QuietLogs quiet;
    report.cases.push_back(robust::run_case(c, run));
    const auto& r = report.cases.back();
    spdlog::set_level(quiet.was);
    spdlog::info("robustness: {} {} in {:.2f} s", c.name, r.as_expected() ? "as expected" : "DEVIATES",
                 r.seconds);
  }
  if (options.work_dir.empty() && !options.keep) {
    std::error_code ec;
    std::filesystem::remove_all(run.work_dir, ec);
  }
  report.machine = machine_info(run.work_dir.parent_path());
  report.seconds = std::chrono::duration<double>(Clock::now() - started).count();
  return report;
}

std::vector<Table> robustness_report_tables(const RobustnessSuiteReport& report) {
  Table matrix;
  matrix.name = "matrix";
  matrix.title = "Outcome per case and stage (ok, error = refused with a clear message, FAILED, - = not run)";
  matrix.columns = {"case"};
  for (robust::Stage s : robust::kStages) matrix.columns.emplace_back(robust::stage_name(s));
  matrix.columns.insert(matrix.columns.end(), {"as expected", "seconds"});
  Table expected;
  expected.name = "cases";
  expected.title = "What each case feeds in and what is expected";
  expected.columns = {"case", "extreme input", "expected"};
  Table details;
  details.name = "details";
  details.title = "Clear errors and deviations";
  details.columns = {"case", "stage", "outcome", "expected", "detail"};
  for (const auto& c : report.cases) {
    std::vector<Cell> row{c.name};
    std::vector<std::string> off;
    for (const auto& s : c.stages) {
      row.emplace_back(short_outcome(s) + (s.as_expected ? "" : " (!)"));
      if (!s.as_expected) off.emplace_back(robust::stage_name(s.stage));
      if (!s.as_expected || s.outcome == robust::Outcome::kClearError) {
        details.add({c.name, std::string(robust::stage_name(s.stage)),
                     std::string(robust::outcome_name(s.outcome)), expected_text(s.expected),
                     s.detail});
      }
    }
    row.emplace_back(off.empty() ? "yes" : fmt::format("NO: {}", fmt::join(off, ", ")));
    row.emplace_back(Cell(c.seconds, 2));
    matrix.add(std::move(row));
    expected.add({c.name, c.extreme, c.expected_text});
  }
  matrix.notes.push_back("(!) marks a stage whose outcome differs from the expected one (see details)");
  matrix.notes.push_back("docs/robustness.md documents each case, its expected outcome per stage and why");
  return {matrix, expected, details};
}

nlohmann::json robustness_report_json(const RobustnessSuiteReport& report,
                                      const std::vector<Table>& tables) {
  nlohmann::json cases = nlohmann::json::array();
  for (const auto& c : report.cases) {
    nlohmann::json stages = nlohmann::json::array();
    for (const auto& s : c.stages) {
      stages.push_back({{"stage", robust::stage_name(s.stage)},
                        {"outcome", robust::outcome_name(s.outcome)},
                        {"expected", robust::outcome_name(s.expected.outcome)},
                        {"expected_message", s.expected.message_part},
                        {"as_expected", s.as_expected},
                        {"detail", s.detail},
                        {"seconds", s.seconds}});
    }
    cases.push_back({{"name", c.name},
                     {"extreme", c.extreme},
                     {"expected", c.expected_text},
                     {"as_expected", c.as_expected()},
                     {"seconds", c.seconds},
                     {"stages", stages}});
  }
  nlohmann::json t = nlohmann::json::array();
  for (const auto& table : tables) t.push_back(table_json(table));
  return {{"suite", "robustness"},
          {"command", report.options.command_line},
          {"options", {{"threads", report.options.threads}, {"quick", report.options.quick}}},
          {"machine", report.machine},
          {"seconds", report.seconds},
          {"deviating_cases", report.deviating()},
          {"cases", cases},
          {"tables", t}};
}

}  // namespace strielad::bench
