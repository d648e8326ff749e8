// SPDX-License-Identifier: Apache-2.0
// Conversion throughput side by side: strielad's converter (in process, all cores,
// timing includes reading the NetCDF input, writing and fsyncing the store and
// finalizing it), nccopy rechunking + deflating the same input (a child process; its
// output fsynced afterwards, timed separately), and the hardware limits: reading the
// input, and reading it while writing a fsynced copy. Every contender starts with the
// input evicted from the page cache (posix_fadvise DONTNEED per input file, after a
// sync()), and the contenders take turns in every round so load changes hit all alike.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "format/manifest.h"

namespace strielad::bench {

struct ContenderRuns {
  std::string name;       // "strielad-convert", "nccopy", "read+copy", "read"
  std::string command;    // what exactly ran
  std::uint64_t input_bytes = 0;   // denominator of MB/s: bytes of the input files
  std::uint64_t output_bytes = 0;  // of the last run
  std::vector<double> seconds;     // total per round (what MB/s uses)
  std::vector<double> fsync_seconds;  // part of `seconds` spent in a separate fsync (nccopy)
  std::vector<double> cpu_seconds;    // user + system per round (process or child)
  double max_resident_before = 0;  // largest input fraction still cached after eviction

  double median_seconds() const;
  double min_seconds() const;
  double max_seconds() const;
  double median_mb_per_s() const;  // input MB / median seconds
  double median_cpu_seconds() const;
};

struct ConversionBenchOptions {
  std::vector<std::filesystem::path> inputs;
  std::vector<std::string> variables;
  std::filesystem::path work;      // scratch; the kept outputs are named below
  std::uint32_t brick = 16;
  format::CodecSpec codec;
  // build::ConvertOptions::fpzip of the main converter run (the extra codecs run without).
  std::vector<std::string> fpzip;
  int threads = 0;                 // converter threads, 0 = all cores
  int repeat = 3;
  bool with_nccopy = true;
  std::vector<std::string> nccopy_extra;  // extra nccopy flags (cache sizes), before the files
  // More converter runs per round with these codecs ("strielad-convert (lz4 5 byte)").
  std::vector<format::CodecSpec> extra_codecs;
  // One more run per round like the main one but reading through netCDF and the page
  // cache ("strielad-convert (buffered input)"): what direct input reads are worth.
  bool buffered_input_run = true;
};

struct ConversionBench {
  // strielad-convert, its buffered-input and extra-codec runs, nccopy (if run), read+copy,
  // read, read (O_DIRECT) (if the file system allows it)
  std::vector<ContenderRuns> contenders;
  std::filesystem::path store;            // the last converted store (kept)
  std::filesystem::path nccopy_output;    // the last nccopy output (kept; empty if none)
  std::vector<std::string> nccopy_argv;   // with the real file names
  std::uint64_t converter_input_bytes = 0;  // ConvertResult::input_bytes (sample bytes)
  double converter_internal_seconds = 0;    // ConvertResult::seconds of the last round

  const ContenderRuns* find(const std::string& name) const;
};

// nccopy flags that let one B-level layer of a variable's output chunks fit the chunk
// cache: "-h BYTES -e SLOTS" (1.5x the layer rounded up to a power of two, at least 64 MiB;
// a prime number of slots above twice the chunks of a layer). With netCDF's default
// cache, rechunking level-chunked input into B^3 chunks thrashes once a layer is larger
// than the cache (measured: 2.3 instead of 36 MB/s on a 1429x1556x48 slab, B = 16).
std::vector<std::string> nccopy_cache_args(std::size_t nx, std::size_t ny, std::uint32_t brick);

// "time/1,height/B,lat/B,lon/B": chunks of one time step and B^3 samples, like bricks.
std::string nccopy_chunk_spec(std::uint32_t brick);

// The nccopy command for one input: -k nc4 -d1 -s -c SPEC [extra] [-V vars] in out.
std::vector<std::string> nccopy_argv(const std::filesystem::path& in,
                                     const std::filesystem::path& out, std::uint32_t brick,
                                     const std::vector<std::string>& extra,
                                     const std::vector<std::string>& only_variables = {});

ConversionBench run_conversion_bench(const ConversionBenchOptions& options);

// Evicts every input (after a sync()) and returns the largest fraction still resident.
double evict_inputs(const std::vector<std::filesystem::path>& inputs);

}  // namespace strielad::bench
