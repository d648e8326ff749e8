// SPDX-License-Identifier: Apache-2.0
#include "bench/io_sweeps.h"

#include <spdlog/spdlog.h>

#include "bench/cpu_time.h"
#include "bench/stopwatch.h"
#include "convert/converter.h"
#include "core/error.h"

namespace strielad::bench {

std::string codec_label(const format::CodecSpec& codec) {
  const std::string label = fmt::format("{} {} {}", codec.name, codec.level, codec.shuffle);
  return codec.predictor == "none" ? label : label + " " + codec.predictor;
}

std::vector<SweepRow> run_sweep(const SweepOptions& o, const std::vector<SweepConfig>& configs) {
  std::uint64_t input_bytes = 0;
  for (const auto& f : o.inputs) input_bytes += std::filesystem::file_size(f);
  std::vector<SweepRow> rows(configs.size());
  std::vector<std::filesystem::path> stores;
  for (std::size_t i = 0; i < configs.size(); ++i) {
    rows[i].config = configs[i];
    rows[i].convert.name = configs[i].label;
    rows[i].convert.input_bytes = input_bytes;
    stores.push_back(o.work / fmt::format("sweep-{}", i));
  }
  for (int round = 0; round < std::max(1, o.repeat); ++round) {
    for (std::size_t i = 0; i < configs.size(); ++i) {
      std::filesystem::remove_all(stores[i]);
      rows[i].convert.max_resident_before =
          std::max(rows[i].convert.max_resident_before, evict_inputs(o.inputs));
      build::ConvertOptions co;
      co.inputs = o.inputs;
      co.store = stores[i];
      co.scan.variables = o.variables;
      co.brick = configs[i].brick;
      co.codec = configs[i].codec;
      co.threads = o.threads;
      const double cpu0 = process_cpu_seconds();
      const Stopwatch clock;
      const auto result = build::convert(co);
      rows[i].convert.seconds.push_back(clock.seconds());
      rows[i].convert.cpu_seconds.push_back(process_cpu_seconds() - cpu0);
      rows[i].convert.output_bytes = result.written_bytes;
      spdlog::info("bench: sweep round {}/{} {}: {:.2f} s", round + 1, std::max(1, o.repeat),
                   configs[i].label, rows[i].convert.seconds.back());
    }
  }
  for (std::size_t i = 0; i < configs.size(); ++i) {
    SweepRow& row = rows[i];
    row.sizes = measure_store_sizes(stores[i]);
    std::uint64_t chunk_bytes = 0;
    for (const auto& v : row.sizes.variables) {
      row.data_bricks += v.data;
      chunk_bytes += v.chunk_bytes;
    }
    row.mean_chunk_bytes =
        row.data_bricks ? static_cast<double>(chunk_bytes) / static_cast<double>(row.data_bricks) : 0;
    BrickReadOptions ro;
    ro.store = stores[i];
    ro.variables = o.variables;
    ro.reads = o.reads;
    ro.first_brick_reads = 0;
    ro.seed = o.seed;
    ro.scratch = o.work;
    ro.coarse_set = false;
    const BrickReadBench reads = run_brick_read_bench(ro);
    if (const auto* cold = reads.find("store cold, level 0")) {
      row.cold_us = cold->latency();
      row.cold_amplification = cold->amplification();
      row.page_amplification = cold->page_amplification();
    }
    if (const auto* warm = reads.find("store warm, level 0")) row.warm_us = warm->latency();
    std::filesystem::remove_all(stores[i]);
  }
  return rows;
}

}  // namespace strielad::bench
