// SPDX-License-Identifier: Apache-2.0
// Camera paths (formats/camera-path.md): keyframes of eye, target and field of view in
// a data set's axis coordinates, so that one path plays over every store of a region.
// Parsing with validation that names the offending JSON path, the canonical writer,
// placement in the world frame (lod/world_frame.h), sampling at any time, and the
// default fly-in path the latency benchmark plays when given no file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "lod/camera.h"
#include "lod/geometry.h"
#include "lod/world_frame.h"

namespace strielad::lod {

// Version of formats/camera-path.md this library reads and writes, and its limits.
inline constexpr std::uint32_t kCameraPathFormatVersion = 1;
inline constexpr std::size_t kMaxCameraPathBytes = 1u << 20;
inline constexpr std::size_t kMaxCameraPathNesting = 8;
inline constexpr std::size_t kMaxKeyframes = 10000;
inline constexpr std::size_t kMaxCameraPathNameBytes = 256;
inline constexpr double kDefaultFovDeg = 45.0;
// Keyframe times lie in [-1e9, 1e9] seconds (about 32 years): differences of times stay
// exact enough to interpolate by.
inline constexpr double kMaxKeyframeTimeS = 1.0e9;
// Farthest a keyframe's eye or target may lie from the world origin once placed in a
// store's world frame (1e6 km, beyond the Moon): keeps every distance and its square
// finite and far from overflow.
inline constexpr double kMaxWorldDistanceKm = 1.0e6;

struct Keyframe {
  double t = 0;        // seconds; strictly increasing along the path
  Vec3 eye{};          // axis coordinates (e.g. lon, lat, height in m or pressure in hPa)
  Vec3 target{};       // axis coordinates; != eye
  double fov_deg = kDefaultFovDeg;  // vertical field of view, in (0, 180)
  friend bool operator==(const Keyframe&, const Keyframe&) = default;
};

struct CameraPath {
  std::string name;  // a label, at most 256 bytes of UTF-8
  std::vector<Keyframe> keyframes;
  friend bool operator==(const CameraPath&, const CameraPath&) = default;
};

// Parses and validates camera-path JSON. Messages name `what` (the file) and the path of
// the offending value: "fly.json: keyframes[2].t: ...".
// \error kInvalidInput for anything formats/camera-path.md says to reject;
// \error kVersionTooNew when format_version is greater than kCameraPathFormatVersion.
CameraPath parse_camera_path(std::string_view json_text, std::string_view what);

// Reads a file (refusing one over kMaxCameraPathBytes unread) and parses it.
// \error kNotFound, kIo naming the file; otherwise as parse_camera_path.
CameraPath load_camera_path_file(const std::filesystem::path& path);

// The rules that need no store, for paths built in code.
// \error kInvalidInput naming `what` and the offending path.
void validate_camera_path(const CameraPath& path, std::string_view what);

// Compact JSON that parses back to an equal path.
// \error kInvalidInput (as validate_camera_path, `what` = "camera path").
std::string camera_path_to_json(const CameraPath& path);

// An interpolated camera position in the world frame.
struct CameraPose {
  Vec3 eye{}, target{};
  double fov_deg = kDefaultFovDeg;
};

// A path placed in a store's world frame, ready to sample.
class WorldCameraPath {
 public:
  // \error kInvalidInput naming `what` and the value's path for a path that fails
  // validate_camera_path, a point the frame cannot place (a pressure <= 0) or that lands
  // farther than kMaxWorldDistanceKm from the origin, and a segment along which the
  // interpolated eye meets the interpolated target.
  WorldCameraPath(const CameraPath& path, const WorldFrame& frame, std::string_view what);

  // The pose at time t (seconds): eye, target and fov interpolated linearly in world
  // space between the keyframes around t; before the first keyframe the first, after
  // the last the last. \error kInvalidArgument for a NaN t.
  CameraPose sample(double t) const;

  double start_time() const { return keys_.front().t; }
  double end_time() const { return keys_.back().t; }

 private:
  struct WorldKey {
    double t;
    CameraPose pose;
  };
  std::vector<WorldKey> keys_;
};

// A camera for a pose (look_at: default up, near/far fitted to `scene`).
Camera pose_camera(const CameraPose& pose, double aspect, const WorldBox& scene);

inline constexpr double kDefaultFlyInSeconds = 20.0;

// The benchmark's default path: from far away, where a 45 degree view (aspect >= 1)
// sees the whole domain from the south at 50 degrees elevation, flying in to a low
// oblique view (25 degrees down, 12% of the domain width south of its centre) over the domain centre, 9 keyframes with
// distances in geometric progression so the approach slows as it nears. Written in the
// frame's axis coordinates. \error kInvalidArgument for a duration that is not finite > 0.
CameraPath default_fly_in_path(const WorldFrame& frame, double duration_s = kDefaultFlyInSeconds);
// The same in the default world frame of `manifest` (\error also as WorldFrame's).
CameraPath default_fly_in_path(const format::Manifest& manifest,
                               double duration_s = kDefaultFlyInSeconds);

}  // namespace strielad::lod
