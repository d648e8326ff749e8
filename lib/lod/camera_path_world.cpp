// SPDX-License-Identifier: Apache-2.0
// Camera paths in a store's world frame: placement, sampling, and the default fly-in.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "lod/camera_path.h"
#include "lod/camera_path_errors.h"

namespace strielad::lod {

using path_detail::fail;
using path_detail::index_path;
using path_detail::key_path;

namespace {

// Eye and target closer than this (1 mm) give no usable view direction.
constexpr double kMinEyeTargetKm = 1e-6;

Vec3 place(const WorldFrame& frame, const Vec3& axis, std::string_view what,
           const std::string& path) {
  const Vec3 w = frame.to_world(axis);
  for (std::size_t i = 0; i < 3; ++i) {
    if (!std::isfinite(w[i])) {
      if (i == 2 && frame.vertical() == VerticalMap::kPressure) {
        fail(ErrorCode::kInvalidInput, what, index_path(path, i),
             "pressure {} has no height: it must be > 0", axis[i]);
      }
      fail(ErrorCode::kInvalidInput, what, index_path(path, i),
           "{} has no finite position in the world frame", axis[i]);
    }
    if (std::fabs(w[i]) > kMaxWorldDistanceKm) {
      fail(ErrorCode::kInvalidInput, what, index_path(path, i),
           "{} lies {:.6g} km from the domain centre, more than {:g} km", axis[i], std::fabs(w[i]),
           kMaxWorldDistanceKm);
    }
  }
  if (length(w) > kMaxWorldDistanceKm) {
    fail(ErrorCode::kInvalidInput, what, path, "lies {:.6g} km from the domain centre, more than {:g} km",
         length(w), kMaxWorldDistanceKm);
  }
  return w;
}

}  // namespace

WorldCameraPath::WorldCameraPath(const CameraPath& path, const WorldFrame& frame,
                                 std::string_view what) {
  validate_camera_path(path, what);
  for (std::size_t i = 0; i < path.keyframes.size(); ++i) {
    const Keyframe& k = path.keyframes[i];
    const std::string p = index_path("keyframes", i);
    WorldKey w{k.t, CameraPose{place(frame, k.eye, what, key_path(p, "eye")),
                               place(frame, k.target, what, key_path(p, "target")), k.fov_deg}};
    // The eye-to-target vector interpolates linearly: its smallest length over the
    // segment from the previous keyframe (or at this keyframe) must be positive.
    const Vec3 d1 = sub(w.pose.target, w.pose.eye);
    double closest = length(d1);
    if (i > 0) {
      const Vec3 d0 = sub(keys_.back().pose.target, keys_.back().pose.eye);
      const Vec3 dd = sub(d1, d0);
      const double dd2 = dot(dd, dd);
      const double s = dd2 > 0 ? std::clamp(-dot(d0, dd) / dd2, 0.0, 1.0) : 0.0;
      closest = std::min(closest, length(add(d0, scale(dd, s))));
    }
    if (!(closest >= kMinEyeTargetKm)) {
      fail(ErrorCode::kInvalidInput, what, p,
           "the eye comes within {:.3g} km of the target {}: the camera must look somewhere",
           closest, i > 0 ? "since the previous keyframe" : "");
    }
    keys_.push_back(w);
  }
}

CameraPose WorldCameraPath::sample(double t) const {
  if (std::isnan(t)) throw make_error(ErrorCode::kInvalidArgument, "camera path time is NaN");
  if (t <= keys_.front().t) return keys_.front().pose;
  if (t >= keys_.back().t) return keys_.back().pose;
  const auto next = std::upper_bound(keys_.begin(), keys_.end(), t,
                                     [](double v, const WorldKey& k) { return v < k.t; });
  const WorldKey& b = *next;
  const WorldKey& a = *(next - 1);
  const double s = std::clamp((t - a.t) / (b.t - a.t), 0.0, 1.0);
  return CameraPose{lerp(a.pose.eye, b.pose.eye, s), lerp(a.pose.target, b.pose.target, s),
                    a.pose.fov_deg + s * (b.pose.fov_deg - a.pose.fov_deg)};
}

Camera pose_camera(const CameraPose& pose, double aspect, const WorldBox& scene) {
  return look_at(pose.eye, pose.target, pose.fov_deg, aspect, scene);
}

CameraPath default_fly_in_path(const WorldFrame& frame, double duration_s) {
  if (!(duration_s > 0) || !(duration_s <= kMaxKeyframeTimeS)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "fly-in duration {} s must be > 0 and at most {} s", duration_s,
                     kMaxKeyframeTimeS);
  }
  constexpr double kDeg = std::numbers::pi / 180.0;
  constexpr int kSegments = 8;
  const WorldBox& d = frame.domain();
  const Vec3 centre = d.center();
  const Vec3 ground{centre[0], centre[1], d.lo[2]};
  const double extent = std::max({d.hi[0] - d.lo[0], d.hi[1] - d.lo[1], 1e-3});
  const double radius = std::max(d.radius(), 1e-3);

  // Start: the bounding sphere fits the vertical field of view with 20% to spare.
  const double start_distance = 1.2 * radius / std::sin(0.5 * kDefaultFovDeg * kDeg);
  const double start_elevation = 50.0 * kDeg;
  // End: 12% of the domain's width south of the centre, looking 25 degrees down at the
  // ground below the centre (on the paper's grid 94 km back and 44 km, i.e. 4.4 km
  // unexaggerated, up).
  const double end_elevation = 25.0 * kDeg;
  const double end_distance = 0.12 * extent / std::cos(end_elevation);

  CameraPath path;
  path.name = "default fly-in";
  for (int k = 0; k <= kSegments; ++k) {
    const double s = static_cast<double>(k) / kSegments;
    const double distance = start_distance * std::pow(end_distance / start_distance, s);
    const double elevation = start_elevation + s * (end_elevation - start_elevation);
    const Vec3 target = lerp(centre, ground, s);
    const Vec3 eye = add(target, Vec3{0, -distance * std::cos(elevation),
                                      distance * std::sin(elevation)});
    Keyframe key;
    key.t = duration_s * s;
    key.eye = frame.to_axis(eye);
    key.target = frame.to_axis(target);
    key.fov_deg = kDefaultFovDeg;
    path.keyframes.push_back(key);
  }
  validate_camera_path(path, "default fly-in path");
  return path;
}

CameraPath default_fly_in_path(const format::Manifest& manifest, double duration_s) {
  return default_fly_in_path(WorldFrame(manifest), duration_s);
}

}  // namespace strielad::lod
