// SPDX-License-Identifier: Apache-2.0
// strielad-bench extract [--dims XxYxZ] [--brick-sizes 20,32,24] [--bricks N] [--repeat N]
//                        [--quick] [--csv FILE] [--json FILE] [--plot FILE.png] [--keep] ...
#include <fmt/ranges.h>

#include <algorithm>
#include <iostream>
#include <memory>

#include "bench/extract_suite.h"
#include "bench/table_writer.h"
#include "commands.h"
#include "suite_output.h"
#include "core/error.h"
#include "synthetic/sample_args.h"

namespace strielad::bench_cmd {
namespace {

struct ExtractFlags {
  std::string dims = "572x624x150";
  std::string vars = "clw,qr,ta,ua";
  std::string work = "/tmp/strielad-bench-extract";
  std::vector<std::uint32_t> brick_sizes{20, 32, build::kDefaultBrick};
  std::size_t bricks = 200;
  int repeat = 5;
  std::vector<std::string> cases;
  bool quick = false, keep = false, no_openvdb = false, no_levels = false;
  std::uint32_t level_brick = build::kDefaultBrick;
  int level_repeat = 3;
  int threads = 0;
  std::uint64_t seed = 1, pick_seed = 42;
  std::string csv, json, plot;
  std::string command_line;
  CLI::App* sub = nullptr;
};

bool given(const ExtractFlags& f, const char* name) { return f.sub->count(name) > 0; }

// Keeps the cases named in `names` (all when empty). Throws kInvalidArgument for an
// unknown name.
std::vector<bench::ExtractCase> pick_cases(std::vector<bench::ExtractCase> all,
                                           const std::vector<std::string>& names) {
  if (names.empty()) return all;
  std::vector<bench::ExtractCase> out;
  for (const auto& n : names) {
    const auto it =
        std::find_if(all.begin(), all.end(), [&](const auto& c) { return c.name == n; });
    if (it == all.end()) {
      std::vector<std::string> known;
      for (const auto& c : all) known.push_back(c.name);
      throw make_error(ErrorCode::kInvalidArgument, "--cases: unknown case '{}' (known: {})", n,
                       fmt::join(known, ", "));
    }
    out.push_back(*it);
  }
  return out;
}

int run(const ExtractFlags& f) {
  bench::ExtractSuiteOptions o;
  if (f.quick) o = bench::quick_extract_options(o);
  if (!f.quick || given(f, "--dims")) o.dims = synthetic::parse_dims(f.dims);
  o.variables = synthetic::parse_variable_list(f.vars);
  o.work = f.work;
  o.keep = f.keep;
  o.seed = f.seed;
  o.pick_seed = f.pick_seed;
  o.threads = f.threads;
  if (!f.quick || given(f, "--brick-sizes")) o.bricks = f.brick_sizes;
  if (!f.quick || given(f, "--bricks")) o.bricks_per_case = f.bricks;
  if (!f.quick || given(f, "--repeat")) o.repeat = f.repeat;
  if (!f.quick || given(f, "--level-brick")) o.level_brick = f.level_brick;
  if (!f.quick || given(f, "--level-repeat")) o.level_repeat = f.level_repeat;
  o.cases = pick_cases(o.cases, f.cases);
  o.openvdb = !f.no_openvdb;
  o.whole_level_openvdb = !f.no_openvdb;
  o.levels = !f.no_levels;
  o.plot_png = f.plot;
  o.command_line = f.command_line;

  const bench::ExtractSuiteReport report = bench::run_extract_suite(o);
  const auto tables = bench::extract_report_tables(report);
  const std::string header = fmt::format(
      "strielad-bench extract: {}x{}x{}, {}, 1 step, bricks {}; suite took {:.0f} s (generate "
      "{:.0f} "
      "s, convert {:.0f} s); {} cores, load average {:.1f} at the end",
      o.dims.x, o.dims.y, o.dims.z, fmt::join(o.variables, ","), fmt::join(o.bricks, ","),
      report.seconds, report.input.generate_seconds, report.convert_seconds,
      report.machine.value("cores", 0u), report.machine.value("load_average_1min_end", -1.0));
  emit_suite_report(header, tables, f.csv, f.json, o.work,
                    [&] { return bench::extract_report_json(report, tables); });
  if (!report.plot_status.empty()) std::cout << "plot: " << report.plot_status << "\n";
  return 0;
}

}  // namespace

void register_extract(CLI::App& app, cli::Action& action, std::string command_line) {
  auto f = std::make_shared<ExtractFlags>();
  auto* sub = app.add_subcommand(
      "extract",
      "Sub-volume extraction on the same bricks: this kernel vs the paper's VTK pipeline, "
      "vtkFlyingEdges3D and OpenVDB; error against run time over octree levels");
  f->sub = sub;
  sub->add_option("--dims", f->dims, "Grid XxYxZ of the generated input (one time step)")
      ->capture_default_str();
  sub->add_option("--vars", f->vars, "Sample variables (the cases need clw, ta, ua)")
      ->capture_default_str();
  sub->add_option("--work", f->work, "Scratch directory (input and stores are reused with --keep)")
      ->capture_default_str();
  sub->add_option("--brick-sizes", f->brick_sizes, "Brick sizes of the per-brick comparison")
      ->delimiter(',')
      ->capture_default_str();
  sub->add_option("--bricks", f->bricks, "Bricks per case and brick size (seeded random choice)")
      ->capture_default_str();
  sub->add_option("--repeat", f->repeat, "Rounds per brick (medians)")->capture_default_str();
  sub->add_option("--cases", f->cases, "Per-brick cases to run: cloud, dense, three (default all)")
      ->delimiter(',');
  sub->add_flag("--no-openvdb", f->no_openvdb, "Leave out OpenVDB volumeToMesh");
  sub->add_flag("--no-levels", f->no_levels, "Skip the error-against-run-time level measurements");
  sub->add_option("--level-brick", f->level_brick, "Brick size of the store measured per level")
      ->capture_default_str();
  sub->add_option("--level-repeat", f->level_repeat, "Rounds per level and thread count (medians)")
      ->capture_default_str();
  sub->add_option("--threads", f->threads,
                  "Threads of the converter and the all-cores level runs "
                  "(default: all cores)");
  sub->add_option("--seed", f->seed, "Seed of the sample data")->capture_default_str();
  sub->add_option("--pick-seed", f->pick_seed, "Seed of the brick choice")->capture_default_str();
  sub->add_flag("--quick", f->quick, "Tiny grid, few bricks, two rounds: checks the harness (CI)");
  sub->add_flag("--keep", f->keep, "Keep the generated input and the stores");
  sub->add_option("--csv", f->csv, "Write the tables as tidy CSV (table,row,column,value)");
  sub->add_option("--json", f->json,
                  "Write the tables, per-brick data, targets and machine info as JSON");
  sub->add_option("--plot", f->plot,
                  "Write the error-against-run-time plot (PNG via gnuplot, with its .gp and .dat)");
  f->command_line = std::move(command_line);
  sub->callback([&action, f] { action = [f] { return run(*f); }; });
}

}  // namespace strielad::bench_cmd
