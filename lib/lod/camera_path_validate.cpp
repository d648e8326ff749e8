// SPDX-License-Identifier: Apache-2.0
// The rules of formats/camera-path.md that need no store.
#include <cmath>

#include <nlohmann/json.hpp>

#include "lod/camera_path.h"
#include "lod/camera_path_errors.h"

namespace strielad::lod {

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
