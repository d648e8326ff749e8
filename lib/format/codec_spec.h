// SPDX-License-Identifier: Apache-2.0
// The codec object of the store manifest (formats/store.md, "Manifest": `codec`): how a
// variable's (or the vertical geometry field's) bricks are compressed, its validation and
// its JSON as each manifest version writes it.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace strielad::format {

// The first version with predictors and per-variable codecs.
inline constexpr std::uint32_t kManifestVersionPredictors = 2;
// The first version with fpzip chunks (CodecSpec::fpzip, IndexEntry::coding).
inline constexpr std::uint32_t kManifestVersionFpzip = 3;
// The first version with error-bounded lossy zfp chunks (CodecSpec::zfp, coding 2).
inline constexpr std::uint32_t kManifestVersionLossy = 6;

// Predictors (formats/store.md, "Predictors").
inline constexpr std::string_view kPredictorNone = "none";
inline constexpr std::string_view kPredictorLorenzo3 = "lorenzo3";

// How a lossy variable's bound was asked for (formats/store.md, "zfp chunks (version 6)"):
// `abs`: the tolerance itself; `rel`: a fraction of the variable's range (max - min of its
// valid samples over every converted step).
enum class LossyMode : std::uint8_t { kAbsolute, kRelative };
std::string_view lossy_mode_name(LossyMode mode);  // "abs", "rel"
// The mode a name gives ("abs", "rel"); nullopt for any other.
std::optional<LossyMode> lossy_mode_from_name(std::string_view name);

// Data bricks coded by zfp's fixed-accuracy mode, each valid sample within `tolerance` of
// the original (verified at conversion; a brick that misses it keeps the codec chain).
struct LossySpec {
  LossyMode mode = LossyMode::kAbsolute;
  double value = 0;      // as asked for: the tolerance (abs) or the fraction of the range (rel)
  double tolerance = 0;  // the absolute bound every valid sample keeps
  friend bool operator==(const LossySpec&, const LossySpec&) = default;
};

// A lossy spec as the manifest's codec object holds it: {mode, value, tolerance}.
nlohmann::json lossy_json(const LossySpec& spec);

// Defaults from the strielad-bench io codec sweep (BENCHMARKS.md): Blosc level 1 (zstd
// level 1) converts 2.4x faster than level 5 (zstd 9) for 9% more bytes; byte shuffle
// beats bit shuffle by 1.5x in size on dense fields. The converter chooses the predictor
// per variable (build/predictor_choice.h); "none" is what a version-1 store used.
struct CodecSpec {
  std::string name = "zstd";       // blosclz, lz4, lz4hc, zlib, zstd
  int level = 1;                   // 0..9
  std::string shuffle = "byte";    // none, byte, bit
  std::string predictor = "none";  // none, lorenzo3 (format version 2)
  // Data bricks may be fpzip chunks where those are smaller (format version 3).
  bool fpzip = false;
  // Data bricks may be zfp chunks within this bound (format version 6); never with fpzip.
  std::optional<LossySpec> zfp = std::nullopt;
  friend bool operator==(const CodecSpec&, const CodecSpec&) = default;
};

// Throws kInvalidArgument naming the bad field (an unknown predictor included; a lossy
// spec whose tolerance is not positive and finite, or with fpzip).
void validate_codec(const CodecSpec& codec);

// A codec object as manifest `version` writes it: version 1 had no predictor.
nlohmann::json codec_json(const CodecSpec& codec, std::uint32_t version);
// Reads and validates a codec object of manifest `version`; throws kCorrupt naming `what`.
CodecSpec codec_from_json(const nlohmann::json& json, std::uint32_t version, std::string_view what);

}  // namespace strielad::format
