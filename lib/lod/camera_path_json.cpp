// SPDX-License-Identifier: Apache-2.0
// Camera-path JSON (formats/camera-path.md): parsing with key, type and syntax checks
// (repeated keys, nesting) naming the offending path; the canonical writer; files.
// The rules of formats/camera-path.md that need no store.

#include <array>
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/strict_json.h"
#include "lod/camera_path.h"
#include "lod/camera_path_errors.h"

namespace strielad::lod {
namespace {

using strict_json::fail;
using strict_json::index_path;
using strict_json::Json;
using strict_json::key_path;
using strict_json::Reader;

constexpr std::array<std::string_view, 3> kTopKeys = {"format_version", "name", "keyframes"};
constexpr std::array<std::string_view, 1> kReservedTopKeys = {"interpolation"};
constexpr std::array<std::string_view, 4> kKeyframeKeys = {"t", "eye", "target", "fov_deg"};
constexpr std::array<std::string_view, 2> kReservedKeyframeKeys = {"up", "step"};

// A JSON integer where another type is expected is "number N" in this format's messages.
constexpr strict_json::Format kCameraPathJson{.name = "camera-path",
                                              .noun = "camera path",
                                              .file_noun = "a camera path",
                                              .version = kCameraPathFormatVersion,
                                              .max_bytes = kMaxCameraPathBytes,
                                              .max_nesting = kMaxCameraPathNesting,
                                              .integers_apart = false};

Vec3 read_point(const Reader& r, const Json& v, const std::string& path) {
  if (!v.is_array() || v.size() != 3) r.wrong_type(v, path, "an array of three numbers [x, y, z]");
  return {r.number(v[0], index_path(path, 0)), r.number(v[1], index_path(path, 1)),
          r.number(v[2], index_path(path, 2))};
}

Keyframe read_keyframe(const Reader& r, const Json& v, const std::string& path) {
  r.object(v, path);
  r.keys(v, path, kKeyframeKeys, kReservedKeyframeKeys);
  Keyframe k;
  k.t = r.number(r.require(v, path, "t"), key_path(path, "t"));
  k.eye = read_point(r, r.require(v, path, "eye"), key_path(path, "eye"));
  k.target = read_point(r, r.require(v, path, "target"), key_path(path, "target"));
  if (const Json* fov = r.find(v, "fov_deg")) k.fov_deg = r.number(*fov, key_path(path, "fov_deg"));
  return k;
}

CameraPath read_path(const Reader& r, const Json& root) {
  if (!root.is_object()) r.wrong_type(root, "", "a JSON object at the top level");
  r.format_version(root);  // first: an older reader must say "newer", not "unknown key"
  r.keys(root, "", kTopKeys, kReservedTopKeys);
  CameraPath path;
  if (const Json* name = r.find(root, "name")) path.name = r.string(*name, "name");
  const Json& keyframes = r.require(root, "", "keyframes");
  r.array(keyframes, "keyframes");
  if (keyframes.size() > kMaxKeyframes) {
    fail(ErrorCode::kInvalidInput, r.what(), "keyframes", "has {} keyframes, more than {}",
         keyframes.size(), kMaxKeyframes);
  }
  for (std::size_t i = 0; i < keyframes.size(); ++i) {
    path.keyframes.push_back(read_keyframe(r, keyframes[i], index_path("keyframes", i)));
  }
  return path;
}

}  // namespace

CameraPath parse_camera_path(std::string_view json_text, std::string_view what) {
  CameraPath path = strict_json::read_document(json_text, what, kCameraPathJson, read_path);
  validate_camera_path(path, what);
  return path;
}

CameraPath load_camera_path_file(const std::filesystem::path& path) {
  return parse_camera_path(strict_json::read_file(path, kCameraPathJson), path.string());
}

std::string camera_path_to_json(const CameraPath& path) {
  validate_camera_path(path, "camera path");
  using nlohmann::ordered_json;
  ordered_json out;
  out["format_version"] = kCameraPathFormatVersion;
  out["name"] = path.name;
  ordered_json keyframes = ordered_json::array();
  for (const Keyframe& k : path.keyframes) {
    ordered_json o;
    o["t"] = k.t;
    o["eye"] = ordered_json::array({k.eye[0], k.eye[1], k.eye[2]});
    o["target"] = ordered_json::array({k.target[0], k.target[1], k.target[2]});
    o["fov_deg"] = k.fov_deg;
    keyframes.push_back(std::move(o));
  }
  out["keyframes"] = std::move(keyframes);
  return out.dump();
}

using path_detail::fail;
using path_detail::index_path;
using path_detail::key_path;

namespace {

bool valid_utf8(const std::string& s) {
  try {
    (void)nlohmann::json(s).dump();  // strict UTF-8 check of nlohmann's writer
    return true;
  } catch (const nlohmann::json::exception&) {
    return false;
  }
}

void check_point(const Vec3& p, std::string_view what, const std::string& path) {
  for (std::size_t i = 0; i < 3; ++i) {
    if (!std::isfinite(p[i])) {
      fail(ErrorCode::kInvalidInput, what, index_path(path, i), "must be a finite number, got {}",
           p[i]);
    }
  }
}

}  // namespace

void validate_camera_path(const CameraPath& path, std::string_view what) {
  if (path.name.size() > kMaxCameraPathNameBytes) {
    fail(ErrorCode::kInvalidInput, what, "name", "has {} bytes, more than {}", path.name.size(),
         kMaxCameraPathNameBytes);
  }
  if (!valid_utf8(path.name)) fail(ErrorCode::kInvalidInput, what, "name", "is not valid UTF-8");
  const auto& keys = path.keyframes;
  if (keys.empty()) {
    fail(ErrorCode::kInvalidInput, what, "keyframes", "needs at least one keyframe");
  }
  if (keys.size() > kMaxKeyframes) {
    fail(ErrorCode::kInvalidInput, what, "keyframes", "has {} keyframes, more than {}",
         keys.size(), kMaxKeyframes);
  }
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const Keyframe& k = keys[i];
    const std::string p = index_path("keyframes", i);
    if (!std::isfinite(k.t)) {
      fail(ErrorCode::kInvalidInput, what, key_path(p, "t"), "must be a finite number, got {}",
           k.t);
    }
    if (std::fabs(k.t) > kMaxKeyframeTimeS) {
      fail(ErrorCode::kInvalidInput, what, key_path(p, "t"), "{} s is outside [-{}, {}] s", k.t,
           kMaxKeyframeTimeS, kMaxKeyframeTimeS);
    }
    if (i > 0 && !(k.t > keys[i - 1].t)) {
      fail(ErrorCode::kInvalidInput, what, key_path(p, "t"),
           "{} is not after the previous keyframe's t {}: times must increase strictly", k.t,
           keys[i - 1].t);
    }
    check_point(k.eye, what, key_path(p, "eye"));
    check_point(k.target, what, key_path(p, "target"));
    if (k.eye == k.target) {
      fail(ErrorCode::kInvalidInput, what, key_path(p, "target"),
           "equals eye: the camera must look somewhere");
    }
    if (!(k.fov_deg > 0 && k.fov_deg < 180)) {
      fail(ErrorCode::kInvalidInput, what, key_path(p, "fov_deg"),
           "must be in (0, 180) degrees, got {}", k.fov_deg);
    }
  }
}

}  // namespace strielad::lod
