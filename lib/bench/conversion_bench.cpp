// SPDX-License-Identifier: Apache-2.0
#include "bench/conversion_bench.h"

#include <fmt/ranges.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>

#include "bench/cpu_time.h"
#include "bench/file_copy.h"
#include "bench/io_sweeps.h"
#include "bench/latency_stats.h"
#include "bench/page_cache.h"
#include "bench/process_runner.h"
#include "bench/stopwatch.h"
#include "convert/converter.h"
#include "core/error.h"
#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"

namespace strielad::bench {
namespace {

ContenderRuns contender(std::string name, std::string command) {
  ContenderRuns c;
  c.name = std::move(name);
  c.command = std::move(command);
  return c;
}

void remove_all_quietly(const std::filesystem::path& p) {
  std::error_code ec;
  std::filesystem::remove_all(p, ec);
}

}  // namespace

double ContenderRuns::median_seconds() const { return median(seconds); }
double ContenderRuns::min_seconds() const {
  return seconds.empty() ? 0 : *std::min_element(seconds.begin(), seconds.end());
}
double ContenderRuns::max_seconds() const {
  return seconds.empty() ? 0 : *std::max_element(seconds.begin(), seconds.end());
}
double ContenderRuns::median_cpu_seconds() const { return median(cpu_seconds); }
double ContenderRuns::median_mb_per_s() const {
  const double s = median_seconds();
  return s > 0 ? static_cast<double>(input_bytes) / 1e6 / s : 0;
}

const ContenderRuns* ConversionBench::find(const std::string& name) const {
  for (const auto& c : contenders) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

std::vector<std::string> nccopy_cache_args(std::size_t nx, std::size_t ny, std::uint32_t brick) {
  const std::uint64_t layer = std::uint64_t{nx} * ny * brick * sizeof(float);
  std::uint64_t bytes = std::uint64_t{64} << 20;
  while (bytes < layer + layer / 2) bytes *= 2;
  const std::uint64_t chunks = ((nx + brick - 1) / brick) * ((ny + brick - 1) / brick);
  const auto is_prime = [](std::uint64_t n) {
    if (n < 2) return false;
    for (std::uint64_t d = 2; d * d <= n; ++d) {
      if (n % d == 0) return false;
    }
    return true;
  };
  std::uint64_t slots = std::max<std::uint64_t>(1009, 2 * chunks + 1);
  while (!is_prime(slots)) ++slots;
  return {"-h", std::to_string(bytes), "-e", std::to_string(slots)};
}

std::string nccopy_chunk_spec(std::uint32_t brick) {
  return fmt::format("time/1,height/{0},lat/{0},lon/{0}", brick);
}

std::vector<std::string> nccopy_argv(const std::filesystem::path& in,
                                     const std::filesystem::path& out, std::uint32_t brick,
                                     const std::vector<std::string>& extra,
                                     const std::vector<std::string>& only_variables) {
  std::vector<std::string> argv = {"nccopy", "-k", "nc4", "-d1", "-s", "-c",
                                   nccopy_chunk_spec(brick)};
  argv.insert(argv.end(), extra.begin(), extra.end());
  if (!only_variables.empty()) {
    argv.push_back("-V");
    argv.push_back(fmt::format("{}", fmt::join(only_variables, ",")));
  }
  argv.push_back(in.string());
  argv.push_back(out.string());
  return argv;
}

double evict_inputs(const std::vector<std::filesystem::path>& inputs) {
  ::sync();
  double worst = 0;
  for (const auto& f : inputs) {
    evict_file(f);
    worst = std::max(worst, page_cache_residency(f).fraction());
  }
  return worst;
}

namespace {

// One conversion bench in progress: where the rounds write, and every contender's runs.
struct ConversionRounds {
  ConversionBench bench;
  std::filesystem::path round_store, copy_dir, nccopy_out, nccopy_log;
  ContenderRuns read, direct_read, copy, nccopy;
  bool direct_read_ran = false;
  // The main converter run (kept store) first, then one per extra codec. Runs 0 and
  // (buffered_input_run) 1 are the main codec, the second reading buffered.
  std::vector<format::CodecSpec> codecs;
  std::size_t main_runs = 0;
  std::vector<ContenderRuns> converts;
};

void check_options(const ConversionBenchOptions& o) {
  if (o.inputs.empty()) throw make_error(ErrorCode::kInvalidArgument, "conversion bench: no inputs");
  if (o.with_nccopy && o.inputs.size() != 1) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "conversion bench: nccopy is compared on one input file (one time step), "
                     "got {}", o.inputs.size());
  }
}

// One contender per converter run of `r.codecs`, named and described.
std::vector<ContenderRuns> converter_contenders(const ConversionBenchOptions& o,
                                                const ConversionRounds& r) {
  const std::string threads = o.threads > 0 ? std::to_string(o.threads) : "all cores";
  std::vector<ContenderRuns> converts;
  for (std::size_t i = 0; i < r.codecs.size(); ++i) {
    const auto& c = r.codecs[i];
    const bool buffered = o.buffered_input_run && i == 1;
    converts.push_back(contender(
        i == 0 ? std::string("strielad-convert")
               : buffered ? std::string("strielad-convert (buffered input)")
                          : fmt::format("strielad-convert ({})", codec_label(c)),
        fmt::format("build::convert in process, brick {}, blosc {} level {} {}-shuffle, "
                    "predictor {}{}, threads {}; includes NetCDF reads ({}), fsync and finalize",
                    o.brick, c.name, c.level, c.shuffle, c.predictor,
                    i >= r.main_runs || o.fpzip.empty() ? std::string()
                                    : fmt::format(", fpzip where it pays for {}", fmt::join(o.fpzip, ",")),
                    threads,
                    buffered ? "every read through netCDF and the page cache"
                             : "raw netCDF-4 planes with O_DIRECT")));
  }
  return converts;
}

// The folders and contenders of a bench on `o`, before its first round.
ConversionRounds plan_rounds(const ConversionBenchOptions& o) {
  std::filesystem::create_directories(o.work);
  std::uint64_t input_bytes = 0;
  for (const auto& f : o.inputs) input_bytes += std::filesystem::file_size(f);

  ConversionRounds r;
  r.bench.store = o.work / "store";
  r.round_store = o.work / "store.round";
  r.copy_dir = o.work / "copy";
  std::filesystem::create_directories(r.copy_dir);
  r.nccopy_out = o.work / "nccopy-d1.nc";
  r.nccopy_log = o.work / "nccopy.log";
  r.bench.nccopy_argv = nccopy_argv(o.inputs.front(), r.nccopy_out, o.brick, o.nccopy_extra);

  r.read = contender("read", fmt::format("read(2) every input file to the end, {} MiB buffer",
                                         kCopyBufferBytes >> 20));
  r.direct_read = contender(
      "read (O_DIRECT)", fmt::format("O_DIRECT reads of every input file to the end, {} MiB each, "
                                     "as the converter reads raw netCDF-4 input",
                                     ingest::SlabReader::kDirectPieceBytes >> 20));
  r.copy = contender("read+copy",
                     fmt::format("read(2) + write(2) a copy of every input file, {} MiB buffer, "
                                 "fsync", kCopyBufferBytes >> 20));
  r.codecs = {o.codec};
  if (o.buffered_input_run) r.codecs.push_back(o.codec);
  r.main_runs = r.codecs.size();
  r.codecs.insert(r.codecs.end(), o.extra_codecs.begin(), o.extra_codecs.end());
  r.converts = converter_contenders(o, r);
  r.nccopy = contender("nccopy", shell_command(r.bench.nccopy_argv) + " (+ fsync of the output)");
  for (auto* c : {&r.read, &r.direct_read, &r.copy, &r.nccopy}) c->input_bytes = input_bytes;
  for (auto& c : r.converts) c.input_bytes = input_bytes;
  return r;
}

// read(2) only, then O_DIRECT reads where the file system allows them.
void time_reads(const ConversionBenchOptions& o, ConversionRounds& r) {
  r.read.max_resident_before = std::max(r.read.max_resident_before, evict_inputs(o.inputs));
  double cpu0 = process_cpu_seconds();
  const CopyResult read = read_files(o.inputs);
  r.read.cpu_seconds.push_back(process_cpu_seconds() - cpu0);
  r.read.seconds.push_back(read.seconds);
  r.read.output_bytes = 0;

  r.direct_read.max_resident_before =
      std::max(r.direct_read.max_resident_before, evict_inputs(o.inputs));
  cpu0 = process_cpu_seconds();
  if (const auto d = read_files_direct(o.inputs, ingest::SlabReader::kDirectPieceBytes)) {
    r.direct_read.cpu_seconds.push_back(process_cpu_seconds() - cpu0);
    r.direct_read.seconds.push_back(d->seconds);
    r.direct_read_ran = true;
  }
}

void time_copy(const ConversionBenchOptions& o, ConversionRounds& r) {
  r.copy.max_resident_before = std::max(r.copy.max_resident_before, evict_inputs(o.inputs));
  const double cpu0 = process_cpu_seconds();
  const CopyResult c = copy_files(o.inputs, r.copy_dir);
  r.copy.cpu_seconds.push_back(process_cpu_seconds() - cpu0);
  r.copy.seconds.push_back(c.seconds);
  r.copy.output_bytes = c.bytes;
  remove_all_quietly(r.copy_dir);
  std::filesystem::create_directories(r.copy_dir);
}

// The converter once per codec; the first run's store is kept as `bench.store`.
void time_converters(const ConversionBenchOptions& o, ConversionRounds& r) {
  for (std::size_t i = 0; i < r.codecs.size(); ++i) {
    ContenderRuns& conv = r.converts[i];
    remove_all_quietly(r.round_store);
    conv.max_resident_before = std::max(conv.max_resident_before, evict_inputs(o.inputs));
    build::ConvertOptions co;
    co.inputs = o.inputs;
    co.store = r.round_store;
    co.scan.variables = o.variables;
    co.brick = o.brick;
    co.codec = r.codecs[i];
    if (i < r.main_runs) co.fpzip = o.fpzip;
    co.scan.direct_input = !(o.buffered_input_run && i == 1);
    co.threads = o.threads;
    const double cpu0 = process_cpu_seconds();
    const Stopwatch clock;
    const build::ConvertResult result = build::convert(co);
    conv.seconds.push_back(clock.seconds());
    conv.cpu_seconds.push_back(process_cpu_seconds() - cpu0);
    conv.output_bytes = result.written_bytes;
    if (i == 0) {
      r.bench.converter_input_bytes = result.input_bytes;
      r.bench.converter_internal_seconds = result.seconds;
      remove_all_quietly(r.bench.store);
      std::filesystem::rename(r.round_store, r.bench.store);
    } else {
      remove_all_quietly(r.round_store);
    }
  }
}

// nccopy as a child process, then an fsync of its output (counted in its time).
void time_nccopy(const ConversionBenchOptions& o, ConversionRounds& r) {
  std::error_code ec;
  std::filesystem::remove(r.nccopy_out, ec);
  r.nccopy.max_resident_before = std::max(r.nccopy.max_resident_before, evict_inputs(o.inputs));
  const ProcessResult p = run_process(r.bench.nccopy_argv, r.nccopy_log);
  if (p.exit_status != 0) {
    throw make_error(ErrorCode::kIo, "'{}' failed with status {}: {}",
                     shell_command(r.bench.nccopy_argv), p.exit_status, p.output_tail);
  }
  const double cpu0 = process_cpu_seconds();
  const Stopwatch sync_clock;
  fsync_file(r.nccopy_out);
  const double fsync_s = sync_clock.seconds();
  r.nccopy.seconds.push_back(p.seconds + fsync_s);
  r.nccopy.fsync_seconds.push_back(fsync_s);
  r.nccopy.cpu_seconds.push_back(p.cpu_seconds + process_cpu_seconds() - cpu0);
  r.nccopy.output_bytes = std::filesystem::file_size(r.nccopy_out);
  r.bench.nccopy_output = r.nccopy_out;
}

void log_round(const ConversionBenchOptions& o, const ConversionRounds& r, int round) {
  std::string line;
  for (const auto& conv : r.converts) line += fmt::format(", {} {:.2f} s", conv.name, conv.seconds.back());
  spdlog::info("bench: conversion round {}/{}: read {:.2f} s, read+copy {:.2f} s{}{}", round + 1,
               std::max(1, o.repeat), r.read.seconds.back(), r.copy.seconds.back(), line,
               o.with_nccopy ? fmt::format(", nccopy {:.2f} s", r.nccopy.seconds.back()) : "");
}

}  // namespace

ConversionBench run_conversion_bench(const ConversionBenchOptions& o) {
  check_options(o);
  ConversionRounds r = plan_rounds(o);
  for (int round = 0; round < std::max(1, o.repeat); ++round) {
    time_reads(o, r);
    time_copy(o, r);
    time_converters(o, r);
    if (o.with_nccopy) time_nccopy(o, r);
    log_round(o, r, round);
  }
  remove_all_quietly(r.copy_dir);
  remove_all_quietly(r.round_store);
  ConversionBench& bench = r.bench;
  for (auto& conv : r.converts) bench.contenders.push_back(std::move(conv));
  if (o.with_nccopy) bench.contenders.push_back(std::move(r.nccopy));
  bench.contenders.push_back(std::move(r.copy));
  bench.contenders.push_back(std::move(r.read));
  if (r.direct_read_ran) bench.contenders.push_back(std::move(r.direct_read));
  return std::move(bench);
}

}  // namespace strielad::bench
