// SPDX-License-Identifier: Apache-2.0
// strielad-bench lossy [--dims XxYxZ] [--vars ta,ua,clw] [--fractions 1e-4,1e-3,1e-2]
//                      [--work DIR] [--repeat N] [--reads N] [--quick] [--csv FILE]
//                      [--json FILE] [--plot FILE.png] [--keep]
#include <fmt/ranges.h>

#include <iostream>
#include <memory>

#include "bench/lossy_suite.h"
#include "bench/report_paths.h"
#include "commands.h"
#include "suite_output.h"
#include "synthetic/sample_args.h"

namespace strielad::bench_cmd {
namespace {

struct LossyFlags {
  std::string dims = "1429x1556x150";
  std::string vars = "ta,ua,clw";
  std::vector<double> fractions{1e-4, 1e-3, 1e-2};
  std::string work = "/tmp/strielad-bench-lossy";
  int repeat = 3;
  std::size_t reads = 300;
  std::uint32_t brick = build::kDefaultBrick;
  int threads = 0;
  bool quick = false, keep = false, no_nccopy = false, no_extraction = false;
  std::string csv, json, plot, command_line;
  CLI::App* sub = nullptr;
};

bool given(const LossyFlags& f, const char* name) { return f.sub->count(name) > 0; }

int run(const LossyFlags& f) {
  bench::LossySuiteOptions o;
  if (f.quick) o = bench::quick_lossy_options(o);
  if (!f.quick || given(f, "--dims")) o.dims = synthetic::parse_dims(f.dims);
  o.variables = synthetic::parse_variable_list(f.vars);
  if (!f.quick || given(f, "--fractions")) o.fractions = f.fractions;
  o.work = f.work;
  if (!f.quick || given(f, "--repeat")) o.repeat = f.repeat;
  if (!f.quick || given(f, "--reads")) o.reads = f.reads;
  if (!f.quick || given(f, "--brick")) o.brick = f.brick;
  o.threads = f.threads;
  o.keep = f.keep;
  o.nccopy = !f.no_nccopy;
  o.extraction = !f.no_extraction;
  o.plot_png = f.plot;
  o.command_line = bench::ReportPaths::for_suite({}, {f.csv, f.json, f.plot}).text(f.command_line);
  const bench::LossySuiteReport report = bench::run_lossy_suite(o);
  const auto tables = bench::lossy_report_tables(report);
  emit_suite_report(fmt::format("strielad-bench lossy: {}x{}x{}, {}, tolerances {} of each range, "
                                "1 step; suite took {:.0f} s",
                                o.dims.x, o.dims.y, o.dims.z, fmt::join(o.variables, ","),
                                fmt::join(o.fractions, ","), report.seconds),
                    tables, f.csv, f.json, o.work,
                    [&] { return bench::lossy_report_json(report, tables); });
  if (!report.plot_status.empty()) std::cout << "plot: " << report.plot_status << "\n";
  return 0;
}

}  // namespace

void register_lossy(CLI::App& app, cli::Action& action, std::string command_line) {
  auto f = std::make_shared<LossyFlags>();
  f->command_line = std::move(command_line);
  auto* sub = app.add_subcommand(
      "lossy",
      "Error-bounded lossy bricks (strielad-convert --lossy): store size against lossless and "
      "NetCDF-4 deflate, cold brick reads, the error reached and what it does to extraction, "
      "conversion throughput, for a sweep of tolerances");
  f->sub = sub;
  sub->add_option("--dims", f->dims, "Grid XxYxZ of the generated input (one time step)")
      ->capture_default_str();
  sub->add_option("--vars", f->vars, "Sample variables (dense: ta, ua; sparse: clw)")
      ->capture_default_str();
  sub->add_option("--fractions", f->fractions,
                  "Tolerances as fractions of each variable's range (comma-separated)")
      ->delimiter(',')
      ->capture_default_str();
  sub->add_option("--work", f->work, "Scratch directory")->capture_default_str();
  sub->add_option("--repeat", f->repeat, "Conversions per store (medians)")->capture_default_str();
  sub->add_option("--reads", f->reads, "Cold brick reads per store")->capture_default_str();
  sub->add_option("--brick", f->brick, "Brick size")->capture_default_str();
  sub->add_option("--threads", f->threads, "Converter threads (default: all cores)");
  sub->add_flag("--quick", f->quick, "Tiny grid, two tolerances, one round: checks the harness");
  sub->add_flag("--no-nccopy", f->no_nccopy, "Skip the NetCDF-4 deflate sizes");
  sub->add_flag("--no-extraction", f->no_extraction, "Skip the scene cases' extraction");
  sub->add_flag("--keep", f->keep, "Keep the generated input and the stores");
  sub->add_option("--csv", f->csv, "Write the tables as tidy CSV");
  sub->add_option("--json", f->json, "Write the tables and machine info as JSON");
  sub->add_option("--plot", f->plot, "Write the chart (PNG via gnuplot, with its .gp and .dat)");
  sub->callback([&action, f] { action = [f] { return run(*f); }; });
}

}  // namespace strielad::bench_cmd
