// SPDX-License-Identifier: Apache-2.0
// strielad-bench robustness [--cases a,b] [--quick] [--work DIR] [--keep] [--threads N]
//                           [--csv FILE] [--json FILE]
// Exit status 1 when some case deviates from its expected outcome.
#include <fmt/format.h>

#include <memory>

#include "bench/robustness_suite.h"
#include "core/error.h"
#include "commands.h"
#include "suite_output.h"

namespace strielad::bench_cmd {
namespace {

struct RobustnessFlags {
  std::vector<std::string> cases;
  std::string work, csv, json, command_line;
  int threads = 2;
  bool keep = false, quick = false;
};

int run(const RobustnessFlags& f) {
  bench::RobustnessSuiteOptions o;
  o.cases = f.cases;
  o.work_dir = f.work;
  o.threads = f.threads;
  o.keep = f.keep;
  o.quick = f.quick;
  o.command_line = f.command_line;
  const auto report = bench::run_robustness_suite(o);
  const auto tables = bench::robustness_report_tables(report);
  const std::size_t deviating = report.deviating();
  const std::string header = fmt::format(
      "strielad-bench robustness: {} cases x 7 stages, {} as expected, {} deviating; suite took "
      "{:.1f} s; {} threads, {} cores",
      report.cases.size(), report.cases.size() - deviating, deviating, report.seconds, o.threads,
      report.machine.value("cores", 0u));
  emit_suite_report(header, tables, f.csv, f.json, o.work_dir,
                    [&] { return bench::robustness_report_json(report, tables); });
  return deviating == 0 ? 0 : kExitStatusChecksFailed;
}

}  // namespace

void register_robustness(CLI::App& app, cli::Action& action, std::string command_line) {
  auto f = std::make_shared<RobustnessFlags>();
  f->command_line = std::move(command_line);
  auto* sub = app.add_subcommand(
      "robustness",
      "Extreme inputs (1e-30 next to 1e30, denormals, fill, NaN/Inf, thresholds at samples, "
      "descending and stretched axes, one-cell grids, longitudes across 180, 2^31 cells) "
      "through conversion, verification, statistics, coarse levels, extraction, the server "
      "and advection; exit status 1 when an outcome differs from the expected one");
  sub->add_option("--cases", f->cases, "Cases to run (default all; see docs/robustness.md)")
      ->delimiter(',');
  sub->add_flag("--quick", f->quick, "A few cases: checks the harness (CI)");
  sub->add_option("--work", f->work, "Scratch directory (default: a fresh one under /tmp)");
  sub->add_flag("--keep", f->keep, "Keep each case's NetCDF input and store");
  sub->add_option("--threads", f->threads, "Converter, extraction and server threads")
      ->capture_default_str();
  sub->add_option("--csv", f->csv, "Write the tables as tidy CSV (table,row,column,value)");
  sub->add_option("--json", f->json, "Write every stage's outcome and detail as JSON");
  sub->callback([f, &action] { action = [f] { return run(*f); }; });
}

}  // namespace strielad::bench_cmd
