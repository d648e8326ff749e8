// SPDX-License-Identifier: Apache-2.0
// strielad-bench grib [--dims XxYxZ] [--repeat N] [--brick N] [--threads N] [--grib-bits N]
//                     [--work DIR] [--quick] [--csv F] [--json F]
#include <fmt/format.h>

#include <memory>

#include "bench/grib_bench.h"
#include "commands.h"
#include "synthetic/sample_args.h"
#include "suite_output.h"

namespace strielad::bench_cmd {
namespace {

struct GribFlags {
  std::string dims = "715x778x75";
  int repeat = 3;
  std::uint32_t brick = 24;
  int threads = 0;
  int grib_bits = 16;
  std::string work = "/tmp/strielad-bench-grib";
  bool quick = false;
  std::string csv, json, command_line;
  CLI::App* sub = nullptr;
};

bool given(const GribFlags& f, const char* name) { return f.sub->count(name) > 0; }

int run(const GribFlags& f) {
  bench::GribBenchOptions o;
  if (f.quick) o = bench::quick_grib_options(o);
  if (!f.quick || given(f, "--dims")) o.dims = synthetic::parse_dims(f.dims);
  if (!f.quick || given(f, "--repeat")) o.repeat = f.repeat;
  o.brick = f.brick;
  o.threads = f.threads;
  o.grib_bits = f.grib_bits;
  o.work = f.work;
  o.command_line = f.command_line;
  const auto report = bench::run_grib_bench(o);
  const auto tables = bench::grib_tables(report);
  const std::string header = fmt::format(
      "strielad-bench grib: {}x{}x{}, {} round(s); input {} in {:.0f} s; suite took {:.0f} s",
      o.dims.x, o.dims.y, o.dims.z, o.repeat, report.reused_input ? "reused" : "generated",
      report.generate_seconds, report.seconds);
  emit_suite_report(header, tables, f.csv, f.json, o.work,
                    [&] { return bench::grib_json(report, tables); });
  return 0;
}

}  // namespace

void register_grib(CLI::App& app, cli::Action& action, std::string command_line) {
  auto f = std::make_shared<GribFlags>();
  f->command_line = std::move(command_line);
  f->sub = app.add_subcommand(
      "grib",
      "GRIB2 conversion: strielad-convert of a GRIB2 sample against grib_to_netcdf followed "
      "by strielad-convert, and strielad-convert of the same data as NetCDF");
  f->sub->add_option("--dims", f->dims, "Grid XxYxZ of the generated sample (1 step)")
      ->capture_default_str();
  f->sub->add_option("--repeat", f->repeat, "Rounds (median, min and max)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  f->sub->add_option("--brick", f->brick, "Brick size of the stores")->capture_default_str();
  f->sub->add_option("--threads", f->threads, "Converter threads (0: all cores)")
      ->capture_default_str();
  f->sub->add_option("--grib-bits", f->grib_bits,
                     "Bits per value of the GRIB2 sample (0: IEEE float32)")
      ->check(CLI::Range(0, 32))
      ->capture_default_str();
  f->sub->add_option("--work", f->work, "Scratch directory; the input is reused")
      ->capture_default_str();
  f->sub->add_flag("--quick", f->quick, "A tiny grid, one round: checks the harness");
  f->sub->add_option("--csv", f->csv, "Write the tables as CSV");
  f->sub->add_option("--json", f->json, "Write the report as JSON");
  f->sub->callback([f, &action] { action = [f] { return run(*f); }; });
}

}  // namespace strielad::bench_cmd
