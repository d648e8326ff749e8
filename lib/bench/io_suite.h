// SPDX-License-Identifier: Apache-2.0
// The `strielad-bench io` suite: on a generated sample dataset it measures conversion
// throughput next to nccopy and the plain read/copy limits, store size per variable next
// to raw and NetCDF-4 deflate level 1, random single-brick read latency warm and cold with
// the bytes each read fetched from disk, the octree overhead, and brick-size and codec
// sweeps. The tool (cmd/strielad-bench) is a thin wrapper; tests call run_io_suite with
// quick options.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/brick_read_bench.h"
#include "bench/conversion_bench.h"
#include "bench/deflate_sizes.h"
#include "bench/io_sweeps.h"
#include "bench/sample_input.h"
#include "bench/store_sizes.h"
#include "bench/table_writer.h"
#include "convert/converter.h"
#include "format/manifest.h"
#include "grid/axis.h"

namespace strielad::bench {

struct IoSuiteOptions {
  Dims3 dims{1429, 1556, 150};  // one full time step of the paper's grid
  std::vector<std::string> variables{"clw", "qr", "ta", "ua"};
  std::filesystem::path work = "/tmp/strielad-bench-io";
  int repeat = 3;                 // rounds per throughput measurement (medians)
  std::size_t reads = 1000;       // random brick reads per latency set
  std::size_t first_brick_reads = 20;
  bool vdb_reads = true;          // also read the bricks through OpenVDB delayed loading
  bool keep = false;              // keep generated inputs, stores and copies
  std::uint64_t seed = 1;         // of the sample data
  std::uint64_t read_seed = 42;   // of the random brick choice
  int threads = 0;                // converter threads, 0 = all cores
  std::uint32_t brick = build::kDefaultBrick;  // main measurements: the converter default
  // Main measurements: the converter's default (predictor chosen per variable).
  format::CodecSpec codec{.predictor = std::string(build::kPredictorAuto)};
  // Variables converted with build::ConvertOptions::fpzip in the main converter run (store
  // format version 3); the extra codecs, the main one included, then run without, and the
  // brick reads add a set of fpzip chunks.
  std::vector<std::string> fpzip;
  bool nccopy = true;             // false: skip the NetCDF competitors
  std::vector<std::string> nccopy_extra;  // extra nccopy flags, after the cache flags
  bool nccopy_tuned_cache = true;         // pass nccopy_cache_args() (see conversion_bench.h)
  // Further converter contenders in the main conversion table (same brick, other codecs;
  // one equal to `codec` is skipped).
  std::vector<format::CodecSpec> extra_codecs{{"lz4", 5, "byte", "auto"},
                                              {"zstd", 1, "byte", "auto"},
                                              {"zstd", 5, "byte", "auto"},
                                              {"zstd", 1, "byte", "none"}};
  bool sweeps = true;
  Dims3 sweep_dims{512, 512, 150};
  std::vector<std::uint32_t> sweep_bricks{12, 16, 20, 24, 32};
  std::vector<format::CodecSpec> sweep_codecs;  // empty: default_sweep_codecs()
  int sweep_repeat = 0;           // 0: same as repeat
  std::size_t sweep_reads = 300;
  std::string command_line;       // how the suite was invoked, for the report
};

// zstd 1/3/5 and lz4, each with byte and bit shuffle.
std::vector<format::CodecSpec> default_sweep_codecs();

// Tiny grid, few reads, one round, two bricks and two codecs: seconds, for CI.
IoSuiteOptions quick_io_options(IoSuiteOptions base);

struct Target {
  std::string name;       // "conversion >= 5x nccopy"
  std::string measured;   // "7.3x (412 MB/s vs 56 MB/s)"
  bool met = false;
  bool evaluated = false; // false when the data for it was not measured
};

struct IoSuiteReport {
  IoSuiteOptions options;
  nlohmann::json machine;
  SampleInput input;
  ConversionBench conversion;
  StoreSizes sizes;
  DeflateSizes deflate;  // empty without nccopy
  std::uint64_t nccopy_total_bytes = 0;
  BrickReadBench reads;
  SampleInput sweep_input;
  std::vector<SweepRow> brick_sweep, codec_sweep;
  std::vector<Target> targets;
  double seconds = 0;  // whole suite
};

IoSuiteReport run_io_suite(const IoSuiteOptions& options);

// Evaluates the io targets (bench/targets.h) from the measurements.
std::vector<Target> evaluate_io_targets(const IoSuiteReport& report);

std::vector<Table> io_report_tables(const IoSuiteReport& report);
nlohmann::json io_report_json(const IoSuiteReport& report, const std::vector<Table>& tables);

}  // namespace strielad::bench
