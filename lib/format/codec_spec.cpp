// SPDX-License-Identifier: Apache-2.0
#include "format/codec_spec.h"

#include <cmath>

#include "core/error.h"
#include "format/json_fields.h"

namespace strielad::format {
namespace {

using nlohmann::json;
using json_fields::get;

void validate_lossy(const LossySpec& z, bool fpzip) {
  if (!(z.value > 0) || !std::isfinite(z.value)) {
    throw make_error(ErrorCode::kInvalidArgument, "zfp {} tolerance {} is not positive and finite",
                     lossy_mode_name(z.mode), z.value);
  }
  if (!(z.tolerance > 0) || !std::isfinite(z.tolerance)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "zfp resolved tolerance {} is not positive and finite", z.tolerance);
  }
  if (z.mode == LossyMode::kAbsolute && z.tolerance != z.value) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "zfp abs tolerance {} differs from its resolved tolerance {}", z.value,
                     z.tolerance);
  }
  if (fpzip) {
    throw make_error(ErrorCode::kInvalidArgument, "a codec cannot have both zfp and fpzip");
  }
}

}  // namespace

std::string_view lossy_mode_name(LossyMode mode) {
  return mode == LossyMode::kRelative ? "rel" : "abs";
}

std::optional<LossyMode> lossy_mode_from_name(std::string_view name) {
  if (name == "abs") return LossyMode::kAbsolute;
  if (name == "rel") return LossyMode::kRelative;
  return std::nullopt;
}

json lossy_json(const LossySpec& spec) {
  return json{{"mode", std::string(lossy_mode_name(spec.mode))}, {"value", spec.value},
              {"tolerance", spec.tolerance}};
}

void validate_codec(const CodecSpec& codec) {
  static const char* kNames[] = {"blosclz", "lz4", "lz4hc", "zlib", "zstd"};
  bool known = false;
  for (const char* n : kNames) known = known || codec.name == n;
  if (!known) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "codec '{}' is not one of blosclz, lz4, lz4hc, zlib, zstd", codec.name);
  }
  if (codec.level < 0 || codec.level > 9) {
    throw make_error(ErrorCode::kInvalidArgument, "codec level {} is not in 0..9", codec.level);
  }
  if (codec.shuffle != "none" && codec.shuffle != "byte" && codec.shuffle != "bit") {
    throw make_error(ErrorCode::kInvalidArgument, "shuffle '{}' is not one of none, byte, bit",
                     codec.shuffle);
  }
  if (codec.predictor != kPredictorNone && codec.predictor != kPredictorLorenzo3) {
    throw make_error(ErrorCode::kInvalidArgument, "predictor '{}' is not one of none, lorenzo3",
                     codec.predictor);
  }
  if (codec.zfp) validate_lossy(*codec.zfp, codec.fpzip);
}

json codec_json(const CodecSpec& c, std::uint32_t version) {
  json j{{"name", c.name}, {"level", c.level}, {"shuffle", c.shuffle}};
  if (version >= kManifestVersionPredictors) j["predictor"] = c.predictor;
  if (c.fpzip) j["fpzip"] = true;
  if (c.zfp) j["zfp"] = lossy_json(*c.zfp);
  return j;
}

CodecSpec codec_from_json(const json& j, std::uint32_t version, std::string_view what) {
  if (!j.is_object()) throw make_error(ErrorCode::kCorrupt, "{}: codec is not an object", what);
  CodecSpec c;
  c.name = get<std::string>(j, "name", what);
  c.level = get<int>(j, "level", what);
  c.shuffle = get<std::string>(j, "shuffle", what);
  if (version >= kManifestVersionPredictors) {
    c.predictor = get<std::string>(j, "predictor", what);
  } else if (j.contains("predictor")) {
    throw make_error(ErrorCode::kCorrupt, "{}: key 'predictor' needs format version {} (this is {})",
                     what, kManifestVersionPredictors, version);
  }
  if (const auto it = j.find("fpzip"); it != j.end()) {
    if (version < kManifestVersionFpzip) {
      throw make_error(ErrorCode::kCorrupt, "{}: key 'fpzip' needs format version {} (this is {})",
                       what, kManifestVersionFpzip, version);
    }
    if (!it->is_boolean()) throw make_error(ErrorCode::kCorrupt, "{}: key 'fpzip' is not a bool", what);
    c.fpzip = it->get<bool>();
  }
  if (const auto it = j.find("zfp"); it != j.end()) {
    if (version < kManifestVersionLossy) {
      throw make_error(ErrorCode::kCorrupt, "{}: key 'zfp' needs format version {} (this is {})",
                       what, kManifestVersionLossy, version);
    }
    if (!it->is_object()) throw make_error(ErrorCode::kCorrupt, "{}: key 'zfp' is not an object", what);
    const std::string where = fmt::format("{}: zfp", what);
    for (const auto& [key, value] : it->items()) {
      if (key != "mode" && key != "value" && key != "tolerance") {
        throw make_error(ErrorCode::kCorrupt, "{}: unknown key '{}'", where, key);
      }
    }
    const auto name = get<std::string>(*it, "mode", where);
    const std::optional<LossyMode> mode = lossy_mode_from_name(name);
    if (!mode) {
      throw make_error(ErrorCode::kCorrupt, "{}: mode '{}' is not one of abs, rel", where, name);
    }
    c.zfp = LossySpec{*mode, get<double>(*it, "value", where), get<double>(*it, "tolerance", where)};
  }
  try {
    validate_codec(c);
  } catch (const Error& e) {
    throw make_error(ErrorCode::kCorrupt, "{}: {}", what, e.what());
  }
  return c;
}

}  // namespace strielad::format
