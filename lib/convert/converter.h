// SPDX-License-Identifier: Apache-2.0
// strielad-convert's library half: plans a store from CF-NetCDF inputs, converts the
// missing time steps (resuming an interrupted conversion), and finalizes the store.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "convert/lossy_option.h"
#include "convert/predictor_choice.h"
#include "format/manifest.h"
#include "ingest/input_catalog.h"

namespace strielad::build {

// Chosen by the strielad-bench io brick sweep (BENCHMARKS.md): 24 is the smallest brick whose
// cold reads stay under 1.25x read amplification (page rounding of the chunk), with the
// smallest stores; the paper used 20.
inline constexpr std::uint32_t kDefaultBrick = 24;

// A converter-only predictor value: decide per variable (build/predictor_choice.h).
inline constexpr std::string_view kPredictorAuto = "auto";

struct ConvertOptions {
  std::vector<std::filesystem::path> inputs;
  std::filesystem::path store;
  ingest::ScanOptions scan;
  std::uint32_t brick = kDefaultBrick;
  // Every variable's codec; predictor "auto", "none" or "lorenzo3".
  format::CodecSpec codec{.predictor = std::string(kPredictorAuto)};
  // Per-variable codecs by variable name (predictor "auto" allowed), e.g. from
  // --codec-for clw=zstd:5:byte:none.
  std::map<std::string, format::CodecSpec> codec_for;
  // Variables whose data bricks are stored as fpzip chunks where those are smaller (store
  // format version 3; "all" for every variable), e.g. from --fpzip clw,qr: smaller cloud
  // fields at about three times the cold read time per fpzip brick (BENCHMARKS.md).
  std::vector<std::string> fpzip;
  // Variables whose data bricks are zfp chunks within an error bound (store format version
  // 6), e.g. from --lossy ta=abs:0.05: never a variable also named by fpzip.
  std::vector<LossyRequest> lossy;
  int threads = 0;  // 0 = all cores
  // Refuse (kUnsupported, before reading any data) a grid whose conversion would need
  // more memory than this (build/conversion_limits.h); 0 = the machine's memory.
  std::uint64_t memory_limit = 0;
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
  std::uint64_t direct_input_bytes = 0;  // of which read with O_DIRECT (ScanOptions)
  std::uint64_t written_bytes = 0;  // step-file bytes written by this run
  std::uint64_t empty = 0, constant = 0, data = 0;
  // Data bricks of lossy variables coded by zfp, and kept lossless because zfp did not
  // reach the bound (counted, logged as a warning).
  std::uint64_t lossy = 0, lossy_fallback = 0;
  double seconds = 0;
  bool finalized = false;
  nlohmann::json summary;  // the manifest summary when finalized
  // Per variable: its codec in the store and, where it was "auto", the trial behind it.
  nlohmann::json codecs = nlohmann::json::object();
  nlohmann::json to_json() const;
};

// Builds the manifest (plan) the inputs and options describe; store_id is set. Resolves
// predictor "auto" per variable by choose_predictor (logged; the trials are appended to
// `trials` when given). The store-wide codec takes the predictor most variables with the
// store-wide Blosc settings use (ties: none); other variables carry their own codec.
// Throws kInvalidArgument for a bad codec, a codec_for or lossy request naming a variable
// not converted, a variable both lossy and fpzip, or a brick larger than one chunk; kUnsupported when a variable's conversion would need more
// memory than options.memory_limit (build/conversion_limits.h). Both are decided from the
// grid's size before any data is read.
format::Manifest plan_store(const ingest::InputCatalog& catalog, const ConvertOptions& options,
                            std::vector<PredictorTrial>* trials = nullptr);

// "clw=zstd:5:byte:none" -> {"clw", codec}: NAME=CODEC:LEVEL:SHUFFLE[:PREDICTOR], the
// predictor defaulting to `default_predictor`. Throws kInvalidArgument naming the text.
std::pair<std::string, format::CodecSpec> parse_codec_for(std::string_view text,
                                                          std::string_view default_predictor);

ConvertResult convert(const ConvertOptions& options);

// Checks that every step file is present and sound, computes the summary and rewrites
// the manifest as complete. Throws kNotFound naming the missing steps.
nlohmann::json finalize_store(const std::filesystem::path& store);

}  // namespace strielad::build
