// SPDX-License-Identifier: Apache-2.0
// strielad-convert's library half: plans a store from CF-NetCDF inputs, converts the
// missing time steps (resuming an interrupted conversion), and finalizes the store.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <vector>

#include "format/manifest.h"
#include "ingest/input_catalog.h"

namespace strielad::build {

// Chosen by the strielad-bench io brick sweep (BENCHMARKS.md): 24 is the smallest brick whose
// cold reads stay under 1.25x read amplification (page rounding of the chunk), with the
// smallest stores; the paper used 20.
inline constexpr std::uint32_t kDefaultBrick = 24;

struct ConvertOptions {
  std::vector<std::filesystem::path> inputs;
  std::filesystem::path store;
  ingest::ScanOptions scan;
  std::uint32_t brick = kDefaultBrick;
  format::CodecSpec codec;
  int threads = 0;  // 0 = all cores
  // Convert only these steps of the store (inclusive), e.g. one Slurm array task.
  std::optional<std::uint32_t> only_first, only_last;
  bool finalize = true;  // finalize when every step is present afterwards
  // Called with (source bytes done, source bytes this run will read).
  std::function<void(std::uint64_t, std::uint64_t)> progress;
};

struct ConvertResult {
  std::uint32_t steps_converted = 0;
  std::uint32_t steps_skipped = 0;  // already present from an earlier run
  std::uint64_t input_bytes = 0;    // source bytes read by this run
  std::uint64_t written_bytes = 0;  // step-file bytes written by this run
  std::uint64_t empty = 0, constant = 0, data = 0;
  double seconds = 0;
  bool finalized = false;
  nlohmann::json summary;  // the manifest summary when finalized
  nlohmann::json to_json() const;
};

// Builds the manifest (plan) the inputs and options describe; store_id is set.
format::Manifest plan_store(const ingest::InputCatalog& catalog, const ConvertOptions& options);

ConvertResult convert(const ConvertOptions& options);

// Checks that every step file is present and sound, computes the summary and rewrites
// the manifest as complete. Throws kNotFound naming the missing steps.
nlohmann::json finalize_store(const std::filesystem::path& store);

}  // namespace strielad::build
