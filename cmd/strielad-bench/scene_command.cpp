// SPDX-License-Identifier: Apache-2.0
// strielad-bench scene [--dims XxYxZ] [--brick N] [--work DIR] [--quick] [--csv F] [--json F]
#include <fmt/format.h>

#include <memory>

#include "bench/scene_economy.h"
#include "commands.h"
#include "synthetic/sample_args.h"
#include "suite_output.h"

namespace strielad::bench_cmd {
namespace {

struct SceneFlags {
  std::string dims = "512x512x150";
  std::uint32_t brick = build::kDefaultBrick;
  std::string work = "/tmp/strielad-bench-scene";
  bool quick = false;
  std::string csv, json, command_line;
  CLI::App* sub = nullptr;
};

bool given(const SceneFlags& f, const char* name) { return f.sub->count(name) > 0; }

int run(const SceneFlags& f) {
  bench::SceneEconomyOptions o;
  if (f.quick) o = bench::quick_scene_economy_options(o);
  if (!f.quick || given(f, "--dims")) o.dims = synthetic::parse_dims(f.dims);
  if (!f.quick || given(f, "--brick")) o.brick = f.brick;
  o.work = f.work;
  o.command_line = f.command_line;
  const auto report = bench::run_scene_economy(o);
  const auto tables = bench::scene_economy_tables(report);
  const std::string header = fmt::format(
      "strielad-bench scene: {}x{}x{}, {} variables, brick {}; {} scenes x 3 views; suite took "
      "{:.0f} s",
      o.dims.x, o.dims.y, o.dims.z, o.variables.size(), o.brick, report.scene_json.size(),
      report.seconds);
  emit_suite_report(header, tables, f.csv, f.json, o.work,
                    [&] { return bench::scene_economy_json(report, tables); });
  return 0;
}

}  // namespace

void register_scene(CLI::App& app, cli::Action& action, std::string command_line) {
  auto f = std::make_shared<SceneFlags>();
  f->command_line = std::move(command_line);
  f->sub = app.add_subcommand(
      "scene",
      "Scene economy: bytes read, bricks decompressed, nodes extracted and bytes sent for "
      "typical scenes and views, against the whole time step");
  f->sub->add_option("--dims", f->dims, "Grid XxYxZ of the generated time step")
      ->capture_default_str();
  f->sub->add_option("--brick", f->brick, "Brick size of the store")->capture_default_str();
  f->sub->add_option("--work", f->work, "Scratch directory; input and store are reused")
      ->capture_default_str();
  f->sub->add_flag("--quick", f->quick, "A small grid: checks the harness");
  f->sub->add_option("--csv", f->csv, "Write the table as CSV");
  f->sub->add_option("--json", f->json, "Write the report as JSON");
  f->sub->callback([f, &action] { action = [f] { return run(*f); }; });
}

}  // namespace strielad::bench_cmd
