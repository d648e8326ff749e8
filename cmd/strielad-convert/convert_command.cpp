// SPDX-License-Identifier: Apache-2.0
#include <spdlog/spdlog.h>

#include <cmath>
#include <iostream>
#include <memory>

#include "convert/converter.h"
#include "cli/progress_bar.h"
#include "cli/step_range.h"
#include "commands.h"
#include "core/error.h"

namespace strielad::convert_cmd {
namespace {

struct ConvertFlags {
  std::vector<std::string> inputs;
  std::string output;
  std::vector<std::string> vars;
  std::uint32_t brick = build::kDefaultBrick;
  std::string time, steps;
  int threads = 0;
  double memory_limit_gib = 0;  // 0: the machine's (or cgroup's) memory
  format::CodecSpec codec{.predictor = std::string(build::kPredictorAuto)};
  std::vector<std::string> codec_for;  // VARIABLE=CODEC:LEVEL:SHUFFLE[:PREDICTOR]
  std::vector<std::string> fpzip;      // variables, or "all"
  std::vector<std::string> lossy;      // VAR=abs:TOL[,VAR=rel:FRACTION...]
  std::string height_var;
  std::vector<std::string> formula_terms;  // NAME=VALUE
  bool nan_as_fill = false, no_finalize = false, json = false, buffered_input = false;
};

void log_summary(const build::ConvertResult& r) {
  spdlog::info("converted {} steps ({} already present): {:.1f} MB read in {:.2f} s ({:.1f} MB/s; "
               "{:.1f} MB of it with direct I/O), {:.1f} MB written",
               r.steps_converted, r.steps_skipped, r.input_bytes / 1e6, r.seconds,
               r.seconds > 0 ? r.input_bytes / 1e6 / r.seconds : 0.0, r.direct_input_bytes / 1e6,
               r.written_bytes / 1e6);
  spdlog::info("bricks: {} with data, {} constant, {} empty (no voxel data stored)", r.data,
               r.constant, r.empty);
  if (r.lossy + r.lossy_fallback > 0) {
    spdlog::info("lossy: {} zfp bricks, {} fallback bricks (zfp missed the bound: kept lossless)",
                 r.lossy, r.lossy_fallback);
  }
  std::string predictors;
  for (const auto& [name, codec] : r.codecs.items()) {
    if (!predictors.empty()) predictors += ", ";
    predictors += fmt::format("{} {}{}", name, codec.value("predictor", "?"),
                              codec.value("fpzip", false) ? " +fpzip"
                              : codec.contains("zfp")
                                  ? fmt::format(" +zfp within {}", codec["zfp"].value("tolerance", 0.0))
                                  : std::string());
  }
  if (!predictors.empty()) spdlog::info("predictors: {}", predictors);
  if (!r.finalized) return;
  const auto& s = r.summary;
  spdlog::info("store: {:.1f} MB from {:.1f} MB of input (ratio {:.2f}), {} nodes per step in {} "
               "levels, octree overhead {:.1f}% of samples ({:.1f}% of stored bytes)",
               s.value("store_bytes", 0.0) / 1e6, s.value("input_bytes", 0.0) / 1e6,
               s.value("ratio", 0.0), s.value("nodes_per_step", 0), s.value("levels", 0),
               s.value("octree_sample_overhead_percent", 0.0),
               s.value("octree_stored_overhead_percent", 0.0));
}

// "P0=100000" -> {"P0", 100000}. \error kInvalidArgument naming the text.
std::pair<std::string, double> parse_formula_term(const std::string& text) {
  const auto eq = text.find('=');
  double value = 0;
  std::size_t used = 0;
  bool ok = eq != std::string::npos && eq > 0 && eq + 1 < text.size();
  if (ok) {
    try {
      value = std::stod(text.substr(eq + 1), &used);
    } catch (const std::exception&) {
      ok = false;
    }
  }
  if (!ok || used != text.size() - eq - 1 || !std::isfinite(value)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "--formula-term '{}': give NAME=VALUE with a finite number, e.g. P0=100000",
                     text);
  }
  return {text.substr(0, eq), value};
}

int run(const ConvertFlags& f) {
  if (f.inputs.empty()) throw make_error(ErrorCode::kInvalidArgument, "no INPUT files given");
  if (f.output.empty()) throw make_error(ErrorCode::kInvalidArgument, "-o STORE is required");
  build::ConvertOptions o;
  for (const auto& in : f.inputs) o.inputs.emplace_back(in);
  o.store = f.output;
  o.scan.variables = f.vars;
  o.scan.nan_as_fill = f.nan_as_fill;
  o.scan.direct_input = !f.buffered_input;
  if (!f.height_var.empty()) o.scan.height_var = f.height_var;
  for (const auto& text : f.formula_terms) {
    const auto [name, value] = parse_formula_term(text);
    if (!o.scan.formula_constants.emplace(name, value).second) {
      throw make_error(ErrorCode::kInvalidArgument, "--formula-term: '{}' given twice", name);
    }
  }
  if (!f.time.empty()) {
    const auto r = cli::parse_step_range(f.time, "--time");
    o.scan.first_step = r.first;
    o.scan.last_step = r.last;
  }
  if (!f.steps.empty()) {
    const auto r = cli::parse_step_range(f.steps, "--steps");
    o.only_first = r.first;
    o.only_last = r.last;
  }
  o.brick = f.brick;
  o.codec = f.codec;
  for (const auto& text : f.codec_for) {
    auto [variable, codec] = build::parse_codec_for(text, f.codec.predictor);
    if (!o.codec_for.emplace(variable, codec).second) {
      throw make_error(ErrorCode::kInvalidArgument, "--codec-for: variable '{}' given twice",
                       variable);
    }
  }
  o.fpzip = f.fpzip;
  for (const auto& text : f.lossy) {
    for (auto& r : build::parse_lossy(text)) o.lossy.push_back(std::move(r));
  }
  o.threads = f.threads;
  o.memory_limit = static_cast<std::uint64_t>(f.memory_limit_gib * 1073741824.0);
  o.finalize = !f.no_finalize;
  std::unique_ptr<cli::ProgressBar> bar;
  std::uint64_t reported = 0;
  o.progress = [&](std::uint64_t done, std::uint64_t total) {
    if (!bar) bar = std::make_unique<cli::ProgressBar>("converting", total / 1000000, "MB");
    bar->advance(done / 1000000 - reported);
    reported = done / 1000000;
  };
  const build::ConvertResult r = build::convert(o);
  if (bar) bar->finish();
  log_summary(r);
  if (f.json) std::cout << r.to_json().dump(2) << "\n";
  return 0;
}

}  // namespace

void register_convert(CLI::App& app, cli::Action& action) {
  auto f = std::make_shared<ConvertFlags>();
  app.add_option("inputs", f->inputs,
                 "CF-NetCDF and GRIB input files, alone or together (a time series may span "
                 "files)");
  app.add_option("-o,--output", f->output, "Store directory to create or resume");
  app.add_option("--vars", f->vars, "Variables to convert (default: every 3D variable)")
      ->delimiter(',');
  // Ranges are checked here because CLI11 2.1 wraps "-1" into a huge unsigned value.
  app.add_option("--brick", f->brick, "Cells per brick edge (the paper used 20)")
      ->capture_default_str()
      ->check(CLI::Range(2, 1024));
  app.add_option("--time", f->time, "Input time steps to include, inclusive: A:B, A:, :B or A");
  app.add_option("--steps", f->steps,
                 "Convert only these steps of the store (inclusive A:B), e.g. one Slurm task");
  app.add_option("--threads", f->threads, "Worker threads (default: all cores)")
      ->check(CLI::Range(0, 4096));
  app.add_option("--memory-limit", f->memory_limit_gib,
                 "Refuse, before reading anything, a conversion estimated to need more than "
                 "this many GiB (default: the machine's or cgroup's memory; the estimate "
                 "assumes incompressible data)")
      ->check(CLI::Range(0.0, 1e9));
  app.add_option("--codec", f->codec.name, "Blosc codec: blosclz, lz4, lz4hc, zlib, zstd")
      ->capture_default_str();
  app.add_option("--level", f->codec.level, "Compression level 0-9")
      ->capture_default_str()
      ->check(CLI::Range(0, 9));
  app.add_option("--shuffle", f->codec.shuffle, "Blosc shuffle: none, byte, bit")
      ->capture_default_str();
  app.add_option("--predictor", f->codec.predictor,
                 "Lossless predictor before Blosc: auto (per variable, from sample bricks of "
                 "the first step), none, lorenzo3")
      ->capture_default_str();
  app.add_option("--codec-for", f->codec_for,
                 "A variable's own codec, VARIABLE=CODEC:LEVEL:SHUFFLE[:PREDICTOR], e.g. "
                 "clw=zstd:5:byte:none (repeatable or comma-separated)")
      ->delimiter(',');
  app.add_option("--fpzip", f->fpzip,
                 "Variables (or 'all') whose data bricks are stored with fpzip where that is "
                 "smaller: on the paper's grid clw about 12% smaller, but a cold read of an fpzip "
                 "brick takes about three times as long; for archives (store format version 3)")
      ->delimiter(',');
  app.add_option("--lossy", f->lossy,
                 "Error-bounded lossy bricks: VAR=abs:TOL (every valid sample within TOL) or "
                 "VAR=rel:FRACTION (TOL = FRACTION x the variable's max - min over all steps), "
                 "comma-separated or repeated. zfp fixed-accuracy, verified per brick (a brick "
                 "that misses the bound stays lossless); missing samples stay missing; not "
                 "together with --fpzip on a variable (store format version 6)");
  app.add_option("--height-var", f->height_var,
                 "Terrain-following levels: the variable holding every sample's height or "
                 "geopotential (on the levels or half levels; default: z_mc, z_ifc, HHL or "
                 "PH + PHB when present, else the z coordinate's CF formula_terms)");
  app.add_option("--formula-term", f->formula_terms,
                 "A CF formula term the files lack, NAME=VALUE in the units the formula "
                 "expects (e.g. P0=100000 for a hybrid sigma-pressure P0 in Pa); repeatable");
  app.add_flag("--nan-as-fill", f->nan_as_fill, "Treat NaN/Inf in the data as missing values");
  app.add_flag("--buffered-input", f->buffered_input,
               "Read every input through netCDF and the page cache. By default, netCDF-4 "
               "variables stored raw (no compression; contiguous or chunked by whole lat/lon "
               "planes) are read with O_DIRECT, which saves the page cache's work on input read "
               "once; buffered reads win only for input already in memory");
  app.add_flag("--no-finalize", f->no_finalize,
               "Do not finalize even if every step is present (finalize runs separately)");
  app.add_flag("--json", f->json, "Print the result as JSON on stdout");
  app.callback([&app, &action, f] {
    if (app.get_subcommands().empty()) action = [f] { return run(*f); };
  });
}

}  // namespace strielad::convert_cmd
