// SPDX-License-Identifier: Apache-2.0
// strielad-bench scaling [--dims XxYxZ] [--fractions 0.25,0.5,1] [--repeat N] [--brick N]
//                        [--work DIR] [--quick] [--csv F] [--json F]
#include <fmt/format.h>

#include <memory>

#include "bench/process_runner.h"
#include "bench/scaling_suite.h"
#include "bench/server_process.h"
#include "commands.h"
#include "core/error.h"
#include "synthetic/sample_args.h"
#include "suite_output.h"

namespace strielad::bench_cmd {
namespace {

struct ScalingFlags {
  std::string dims = "1429x1556x150";
  std::vector<double> fractions{0.25, 0.5, 1.0};
  int repeat = 3;
  std::uint32_t brick = build::kDefaultBrick;
  std::string work = "/tmp/strielad-bench-scaling";
  bool quick = false;
  std::string csv, json, command_line;
  CLI::App* sub = nullptr;
};

bool given(const ScalingFlags& f, const char* name) { return f.sub->count(name) > 0; }

int run(const ScalingFlags& f) {
  bench::ScalingSuiteOptions o;
  if (f.quick) o = bench::quick_scaling_options(o);
  if (!f.quick || given(f, "--dims")) o.dims = synthetic::parse_dims(f.dims);
  if (!f.quick || given(f, "--brick")) o.brick = f.brick;
  if (!f.quick || given(f, "--repeat")) o.repeat = f.repeat;
  o.fractions = f.fractions;
  o.work = f.work;
  o.command_line = f.command_line;
  o.server_binary = bench::find_serve_binary();
  o.mpirun = bench::find_program("mpirun").value_or(std::filesystem::path{});
  const auto report = bench::run_scaling_suite(o);
  const auto tables = bench::scaling_tables(report);
  const std::string header = fmt::format(
      "strielad-bench scaling: grids {} of {}x{}x{}, {} round(s); suite took {:.0f} s",
      fmt::join(o.fractions, ", "), o.dims.x, o.dims.y, o.dims.z, o.repeat, report.seconds);
  emit_suite_report(header, tables, f.csv, f.json, o.work,
                    [&] { return bench::scaling_json(report, tables); });
  return 0;
}

}  // namespace

void register_scaling(CLI::App& app, cli::Action& action, std::string command_line) {
  auto f = std::make_shared<ScalingFlags>();
  f->command_line = std::move(command_line);
  f->sub = app.add_subcommand(
      "scaling",
      "Scaling: cost against grid size (a quarter, half and all of a full time step), "
      "threads (1 and 2), MPI ranks of strielad-serve (1 to 3) and sub-volumes (1 to 8)");
  f->sub->add_option("--dims", f->dims, "The whole grid XxYxZ (the paper's time step)")
      ->capture_default_str();
  f->sub->add_option("--fractions", f->fractions,
                     "Grid sizes as fractions of the whole grid's cells, each in (0, 1]")
      ->delimiter(',')
      ->capture_default_str();
  f->sub->add_option("--repeat", f->repeat, "Rounds per figure (median, min and max)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  f->sub->add_option("--brick", f->brick, "Brick size of the stores")->capture_default_str();
  f->sub->add_option("--work", f->work, "Scratch directory; inputs and stores are reused")
      ->capture_default_str();
  f->sub->add_flag("--quick", f->quick, "A small grid, one round: checks the harness");
  f->sub->add_option("--csv", f->csv, "Write the tables as CSV");
  f->sub->add_option("--json", f->json, "Write the report as JSON");
  f->sub->callback([f, &action] { action = [f] { return run(*f); }; });
}

}  // namespace strielad::bench_cmd
