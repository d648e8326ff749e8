// SPDX-License-Identifier: Apache-2.0
// strielad-bench geometry [--dims XxYxZ] [--steps N] [--repeat N] [--brick N] [--threads N]
//                         [--work DIR] [--quick] [--csv F] [--json F]
#include <fmt/format.h>

#include <memory>

#include "bench/geometry_bench.h"
#include "commands.h"
#include "synthetic/sample_args.h"
#include "suite_output.h"

namespace strielad::bench_cmd {
namespace {

struct GeometryFlags {
  std::string dims = "286x312x60";
  std::size_t steps = 2;
  int repeat = 3;
  std::uint32_t brick = 24;
  int threads = 0;
  std::string work = "/tmp/strielad-bench-geometry";
  bool quick = false;
  std::string csv, json, command_line;
  CLI::App* sub = nullptr;
};

bool given(const GeometryFlags& f, const char* name) { return f.sub->count(name) > 0; }

int run(const GeometryFlags& f) {
  bench::GeometryBenchOptions o;
  if (f.quick) o = bench::quick_geometry_options(o);
  if (!f.quick || given(f, "--dims")) o.dims = synthetic::parse_dims(f.dims);
  if (!f.quick || given(f, "--repeat")) o.repeat = f.repeat;
  o.steps = f.steps;
  o.brick = f.brick;
  o.threads = f.threads;
  o.work = f.work;
  o.command_line = f.command_line;
  const auto report = bench::run_geometry_bench(o);
  const auto tables = bench::geometry_tables(report);
  const std::string header =
      fmt::format("strielad-bench geometry: {}x{}x{}, {} steps, {} round(s); suite took {:.0f} s",
                  o.dims.x, o.dims.y, o.dims.z, o.steps, o.repeat, report.seconds);
  emit_suite_report(header, tables, f.csv, f.json, o.work,
                    [&] { return bench::geometry_json(report, tables); });
  return 0;
}

}  // namespace

void register_geometry(CLI::App& app, cli::Action& action, std::string command_line) {
  auto f = std::make_shared<GeometryFlags>();
  f->command_line = std::move(command_line);
  f->sub = app.add_subcommand(
      "geometry",
      "Grid geometries: conversion and level-0 extraction of the ICON-like, hybrid "
      "sigma-pressure and curvilinear samples against the rectilinear sample of the same size");
  f->sub->add_option("--dims", f->dims, "Grid XxYxZ of the generated samples")
      ->capture_default_str();
  f->sub->add_option("--steps", f->steps, "Time steps of the samples")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  f->sub->add_option("--repeat", f->repeat, "Rounds (median, min and max)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  f->sub->add_option("--brick", f->brick, "Brick size of the stores")->capture_default_str();
  f->sub->add_option("--threads", f->threads, "Converter threads (0: all cores)")
      ->capture_default_str();
  f->sub->add_option("--work", f->work, "Scratch directory; the inputs are reused")
      ->capture_default_str();
  f->sub->add_flag("--quick", f->quick, "A tiny grid, one round: checks the harness");
  f->sub->add_option("--csv", f->csv, "Write the tables as CSV");
  f->sub->add_option("--json", f->json, "Write the report as JSON");
  f->sub->callback([f, &action] { action = [f] { return run(*f); }; });
}

}  // namespace strielad::bench_cmd
