// SPDX-License-Identifier: Apache-2.0
// Parameter sweeps for picking defaults from data: the same input converted with several
// brick sizes or codecs, each configuration measured for conversion throughput (median of
// rounds; configurations take turns within a round, input evicted before each), store
// size per variable, node count, and warm/cold single-brick read latency.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/brick_read_bench.h"
#include "bench/conversion_bench.h"
#include "bench/store_sizes.h"
#include "format/manifest.h"

namespace strielad::bench {

struct SweepConfig {
  std::string label;  // "B=16", "zstd 5 byte"
  std::uint32_t brick = 16;
  format::CodecSpec codec;
};

struct SweepRow {
  SweepConfig config;
  ContenderRuns convert;  // seconds per round, input bytes
  StoreSizes sizes;
  std::uint64_t data_bricks = 0;
  double mean_chunk_bytes = 0;  // over data bricks of all levels
  Summary cold_us, warm_us;     // level-0 data bricks
  double cold_amplification = 0, page_amplification = 0;
};

struct SweepOptions {
  std::vector<std::filesystem::path> inputs;
  std::vector<std::string> variables;
  std::filesystem::path work;
  int repeat = 3;
  std::size_t reads = 300;
  int threads = 0;
  std::uint64_t seed = 42;
};

std::vector<SweepRow> run_sweep(const SweepOptions& options, const std::vector<SweepConfig>& configs);

// "zstd 5 byte" style label, with the predictor after it unless it is "none".
std::string codec_label(const format::CodecSpec& codec);

}  // namespace strielad::bench
