// SPDX-License-Identifier: Apache-2.0
#include "format/codec_spec.h"

#include "core/error.h"
#include "format/json_fields.h"

namespace strielad::format {
namespace {

using nlohmann::json;
using json_fields::get;

}  // namespace

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
}

json codec_json(const CodecSpec& c, std::uint32_t version) {
  json j{{"name", c.name}, {"level", c.level}, {"shuffle", c.shuffle}};
  if (version >= kManifestVersionPredictors) j["predictor"] = c.predictor;
  if (c.fpzip) j["fpzip"] = true;
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
  try {
    validate_codec(c);
  } catch (const Error& e) {
    throw make_error(ErrorCode::kCorrupt, "{}: {}", what, e.what());
  }
  return c;
}

}  // namespace strielad::format
