// SPDX-License-Identifier: Apache-2.0
// strielad-bench advect [--repeat N] [--trajectories N] [--quick] [--csv FILE] [--json FILE]
//                       [--plot FILE.png]
#include <fmt/format.h>

#include <iostream>
#include <memory>

#include "bench/advect_suite.h"
#include "bench/report_paths.h"
#include "commands.h"
#include "suite_output.h"

namespace strielad::bench_cmd {
namespace {

struct AdvectFlags {
  int repeat = 5;
  int trajectories = 16;
  bool quick = false;
  std::string csv, json, plot, command_line;
};

int run(const AdvectFlags& f) {
  bench::AdvectSuiteOptions o;
  o.repeat = f.repeat;
  o.trajectories = f.trajectories;
  o.quick = f.quick;
  o.plot_png = f.plot;
  // Quoted in the plot's data file as well as in the reports.
  o.command_line = bench::ReportPaths::for_suite({}, {f.csv, f.json, f.plot}).text(f.command_line);
  const auto report = bench::run_advect_suite(o);
  const auto tables = bench::advect_report_tables(report);
  const std::string header = fmt::format(
      "strielad-bench advect: {} runs on {} start points each, median of {} timed repeats; "
      "suite took {:.0f} s; {} cores",
      report.runs.size(), o.quick ? 2 : o.trajectories, o.quick ? 1 : o.repeat, report.seconds,
      report.machine.value("cores", 0u));
  emit_suite_report(header, tables, f.csv, f.json, {},
                    [&] { return bench::advect_report_json(report, tables); });
  if (!report.plot_status.empty()) std::cout << "plot: " << report.plot_status << "\n";
  return 0;
}

}  // namespace

void register_advect(CLI::App& app, cli::Action& action, std::string command_line) {
  auto f = std::make_shared<AdvectFlags>();
  f->command_line = std::move(command_line);
  auto* sub = app.add_subcommand(
      "advect",
      "Error against run time of the advection integrators (Euler, RK4, Dormand-Prince 5(4), "
      "Rosenbrock RODAS3) on flows with known trajectories, stiff ones included, and on the "
      "sample generator's wind");
  sub->add_option("--repeat", f->repeat, "Timed runs per setting")->capture_default_str();
  sub->add_option("--trajectories", f->trajectories, "Start points per flow")->capture_default_str();
  sub->add_flag("--quick", f->quick, "Few settings and start points: checks the harness");
  sub->add_option("--csv", f->csv, "Write the tables as CSV");
  sub->add_option("--json", f->json, "Write the report as JSON");
  sub->add_option("--plot", f->plot,
                  "Write the work-precision diagrams (PNG via gnuplot, with its .gp and .dat)");
  sub->callback([f, &action] { action = [f] { return run(*f); }; });
}

}  // namespace strielad::bench_cmd
