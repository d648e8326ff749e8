// SPDX-License-Identifier: Apache-2.0
// Random single-brick reads from a store (Store::read_brick: one pread of the chunk,
// checksum, Blosc decompression) with the step file evicted from the page cache before
// every read (cold) or after a warm-up pass (warm), the bytes each read fetched from disk
// (/proc/self/io read_bytes, or mincore residency where that counter does not move), and
// the same regions read from a chunked NetCDF-4 file with nc_get_vara_float and through
// OpenVDB's delayed loading of a level-0 .vdb (peers/delayed_region_reader.h).
// The store's index sections are loaded before timing starts (a reader keeps them), so a
// cold read costs exactly the chunk; `first_brick` measures open + index + one brick.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/latency_stats.h"
#include "octree/octree_layout.h"

namespace strielad {
class Store;
}

namespace strielad::bench {

struct ReadSample {
  std::uint32_t variable = 0;
  NodeId node = 0;
};

// kFpzip: bricks of any level whose chunk is an fpzip chunk (store version 3).
enum class LevelFilter { kLevel0, kCoarse, kAny, kFpzip };

// `count` data-bearing nodes of step 0 drawn uniformly without replacement (with
// replacement only when fewer exist) over all variables, deterministic for `seed`.
std::vector<ReadSample> pick_data_nodes(const Store& store, LevelFilter filter, std::size_t count,
                                        std::uint64_t seed);

enum class DiskByteMethod { kProcSelfIo, kMincore };
const char* disk_byte_method_name(DiskByteMethod m);

struct ReadSet {
  std::string name;         // "store cold, level 0"
  std::string description;  // what one read does
  std::vector<double> latency_us;
  std::vector<double> disk_bytes;     // fetched from disk per read
  std::vector<double> payload_bytes;  // compressed chunk bytes per read (0: unknown)
  std::vector<double> page_bytes;     // the chunk's bytes rounded out to whole pages

  Summary latency() const { return summarize(latency_us); }
  double mean_disk_bytes() const;
  double mean_payload_bytes() const;
  // Total disk bytes / total chunk bytes (NaN when the payload is unknown).
  double amplification() const;
  double amplification_p50() const;
  // The amplification whole pages alone impose on these chunks.
  double page_amplification() const;
};

struct BrickReadOptions {
  std::filesystem::path store;
  std::filesystem::path netcdf;  // chunked NetCDF-4 copy of the input; empty: skip
  // Level 0 of every store variable as .vdb (vdb::write_level_vdb), in store variable
  // order, read through OpenVDB delayed loading; empty: skip.
  std::vector<std::filesystem::path> vdb_files;
  std::vector<std::string> variables;  // netCDF names, in store variable order
  std::size_t reads = 1000;            // per set
  std::size_t first_brick_reads = 20;  // fresh opens
  std::uint64_t seed = 42;
  std::filesystem::path scratch;       // for the /proc/self/io probe
  bool coarse_set = true;
};

struct BrickReadBench {
  DiskByteMethod method = DiskByteMethod::kProcSelfIo;
  double resident_after_evict = 0;  // store step file fraction cached right after evict
  std::vector<ReadSet> sets;
  const ReadSet* find(const std::string& name) const;
};

BrickReadBench run_brick_read_bench(const BrickReadOptions& options);

}  // namespace strielad::bench
