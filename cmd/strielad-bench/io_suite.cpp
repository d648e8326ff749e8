// SPDX-License-Identifier: Apache-2.0
// strielad-bench io [--dims XxYxZ] [--vars a,b] [--work DIR] [--repeat N] [--reads N]
//                   [--quick] [--csv FILE] [--json FILE] [--keep] ...
#include <fmt/ranges.h>

#include <iostream>
#include <memory>

#include "bench/io_suite.h"
#include "bench/table_writer.h"
#include "commands.h"
#include "suite_output.h"
#include "core/error.h"
#include "synthetic/sample_args.h"

namespace strielad::bench_cmd {
namespace {

struct IoFlags {
  std::string dims = "1429x1556x150";
  std::string vars = "clw,qr,ta,ua";
  std::string work = "/tmp/strielad-bench-io";
  int repeat = 3;
  std::size_t reads = 1000;
  bool quick = false, keep = false, no_nccopy = false, no_sweeps = false, nccopy_untuned = false;
  std::string csv, json;
  std::uint32_t brick = build::kDefaultBrick;
  // The converter's default (bench::IoSuiteOptions): predictor chosen per variable.
  format::CodecSpec codec = bench::IoSuiteOptions{}.codec;
  std::vector<std::string> fpzip;
  int threads = 0;
  std::uint64_t seed = 1;
  std::string sweep_dims = "512x512x150";
  std::vector<std::uint32_t> sweep_bricks{12, 16, 20, 24, 32};
  std::size_t sweep_reads = 300;
  int sweep_repeat = 0;
  std::vector<std::string> nccopy_args;
  std::vector<std::string> sweep_codecs;  // name:level:shuffle
  std::string command_line;
  CLI::App* sub = nullptr;
};

bool given(const IoFlags& f, const char* name) { return f.sub->count(name) > 0; }

// "zstd:3:byte" -> CodecSpec; checked by format::validate_codec.
format::CodecSpec parse_codec(const std::string& text) {
  const auto a = text.find(':'), b = text.rfind(':');
  if (a == std::string::npos || a == b) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "--sweep-codecs: '{}' is not NAME:LEVEL:SHUFFLE (e.g. zstd:3:byte)", text);
  }
  format::CodecSpec c;
  c.name = text.substr(0, a);
  try {
    c.level = std::stoi(text.substr(a + 1, b - a - 1));
  } catch (const std::exception&) {
    throw make_error(ErrorCode::kInvalidArgument, "--sweep-codecs: bad level in '{}'", text);
  }
  c.shuffle = text.substr(b + 1);
  format::validate_codec(c);
  return c;
}

int run(const IoFlags& f) {
  bench::IoSuiteOptions o;
  if (f.quick) o = bench::quick_io_options(o);
  if (!f.quick || given(f, "--dims")) o.dims = synthetic::parse_dims(f.dims);
  o.variables = synthetic::parse_variable_list(f.vars);
  o.work = f.work;
  if (!f.quick || given(f, "--repeat")) o.repeat = f.repeat;
  if (!f.quick || given(f, "--reads")) o.reads = f.reads;
  o.keep = f.keep;
  o.brick = f.brick;
  o.codec = f.codec;
  o.fpzip = f.fpzip;
  o.threads = f.threads;
  o.seed = f.seed;
  o.nccopy = !f.no_nccopy;
  o.nccopy_extra = f.nccopy_args;
  o.nccopy_tuned_cache = !f.nccopy_untuned;
  o.sweeps = !f.no_sweeps;
  if (!f.quick || given(f, "--sweep-dims")) o.sweep_dims = synthetic::parse_dims(f.sweep_dims);
  if (!f.quick || given(f, "--sweep-bricks")) o.sweep_bricks = f.sweep_bricks;
  if (!f.quick || given(f, "--sweep-reads")) o.sweep_reads = f.sweep_reads;
  if (!f.quick || given(f, "--sweep-repeat")) o.sweep_repeat = f.sweep_repeat;
  if (given(f, "--sweep-codecs")) {
    o.sweep_codecs.clear();
    for (const auto& c : f.sweep_codecs) o.sweep_codecs.push_back(parse_codec(c));
  }
  o.command_line = f.command_line;

  const bench::IoSuiteReport report = bench::run_io_suite(o);
  const auto tables = bench::io_report_tables(report);
  emit_suite_report(fmt::format("strielad-bench io: {}x{}x{}, {}, 1 step; suite took {:.0f} s",
                                o.dims.x, o.dims.y, o.dims.z, fmt::join(o.variables, ","),
                                report.seconds),
                    tables, f.csv, f.json, o.work,
                    [&] { return bench::io_report_json(report, tables); });
  return 0;
}

}  // namespace

void register_io(CLI::App& app, cli::Action& action, std::string command_line) {
  auto f = std::make_shared<IoFlags>();
  auto* sub = app.add_subcommand(
      "io", "Conversion throughput vs nccopy and copy, store sizes vs deflate, brick read latency");
  f->sub = sub;
  sub->add_option("--dims", f->dims, "Grid XxYxZ of the generated input (one time step)")
      ->capture_default_str();
  sub->add_option("--vars", f->vars, "Sample variables")->capture_default_str();
  sub->add_option("--work", f->work, "Scratch directory (inputs are reused from it with --keep)")
      ->capture_default_str();
  sub->add_option("--repeat", f->repeat, "Rounds per throughput measurement (medians)")
      ->capture_default_str();
  sub->add_option("--reads", f->reads, "Random brick reads per latency set")->capture_default_str();
  sub->add_flag("--quick", f->quick, "Tiny grid, one round, few reads: checks the harness (CI)");
  sub->add_option("--csv", f->csv, "Write the tables as tidy CSV (table,row,column,value)");
  sub->add_option("--json", f->json, "Write the tables, targets and machine info as JSON");
  sub->add_flag("--keep", f->keep, "Keep the generated inputs, stores and NetCDF copies");
  sub->add_option("--brick", f->brick, "Brick size of the main measurements")->capture_default_str();
  sub->add_option("--codec", f->codec.name, "Codec of the main measurements")->capture_default_str();
  sub->add_option("--level", f->codec.level, "Codec level of the main measurements")
      ->capture_default_str();
  sub->add_option("--shuffle", f->codec.shuffle, "Shuffle of the main measurements")
      ->capture_default_str();
  sub->add_option("--predictor", f->codec.predictor,
                  "Predictor of the main measurements: auto (per variable, the converter's "
                  "default), none or lorenzo3")
      ->capture_default_str();
  sub->add_option("--fpzip", f->fpzip,
                  "Variables (or 'all') converted with strielad-convert --fpzip in the main converter "
                  "run (store format version 3); the extra codecs, the main one included, run "
                  "without it; adds a read set of the fpzip chunks")
      ->delimiter(',');
  sub->add_option("--threads", f->threads, "Converter threads (default: all cores)");
  sub->add_option("--seed", f->seed, "Seed of the sample data")->capture_default_str();
  sub->add_flag("--no-nccopy", f->no_nccopy, "Skip the NetCDF competitors");
  sub->add_flag("--nccopy-default-cache", f->nccopy_untuned,
                "Run nccopy with netCDF's default chunk cache (thrashes on large grids)");
  sub->add_flag("--no-sweeps", f->no_sweeps, "Skip the brick-size and codec sweeps");
  sub->add_option("--sweep-dims", f->sweep_dims, "Grid of the sweeps")->capture_default_str();
  sub->add_option("--sweep-bricks", f->sweep_bricks, "Brick sizes of the sweep")
      ->delimiter(',')
      ->capture_default_str();
  sub->add_option("--sweep-reads", f->sweep_reads, "Brick reads per sweep configuration")
      ->capture_default_str();
  sub->add_option("--sweep-repeat", f->sweep_repeat, "Rounds per sweep configuration (0: --repeat)")
      ->capture_default_str();
  sub->add_option("--sweep-codecs", f->sweep_codecs,
                  "Codecs of the codec sweep as NAME:LEVEL:SHUFFLE (default: zstd 1/3/5 and lz4 5, "
                  "byte and bit shuffle)")
      ->delimiter(',');
  sub->add_option("--nccopy-arg", f->nccopy_args,
                  "Extra nccopy argument (repeatable), e.g. --nccopy-arg=-h --nccopy-arg=256M")
      ->allow_extra_args(false);
  f->command_line = std::move(command_line);
  sub->callback([&action, f] { action = [f] { return run(*f); }; });
}

}  // namespace strielad::bench_cmd
