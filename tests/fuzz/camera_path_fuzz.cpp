// SPDX-License-Identifier: Apache-2.0
// Fuzzes the camera-path parser (formats/camera-path.md) and its placement in the world
// frames of a height and a pressure store: they must reject with strielad::Error, never
// crash. A path that parses must survive the canonical round trip unchanged, and a path
// that places must sample to finite poses that make valid cameras; anything else is a
// bug and aborts.
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "format/manifest.h"
#include "fuzz/fuzz_target.h"
#include "lod/camera_path.h"
#include "lod/world_frame.h"

using namespace strielad;

namespace {

format::Manifest manifest(AxisKind z_kind) {
  format::Manifest m;
  m.x = Axis{"lon", AxisKind::kLongitude, "degrees_east", "", "", "", {4.5, 9.5, 14.5}};
  m.y = Axis{"lat", AxisKind::kLatitude, "degrees_north", "", "", "", {54.5, 47.5}};
  if (z_kind == AxisKind::kPressure) {
    m.z = Axis{"plev", AxisKind::kPressure, "hPa", "", "", "down", {1000, 500, 100}};
  } else {
    m.z = Axis{"height", AxisKind::kHeight, "m", "", "", "up", {21000, 20}};
  }
  m.time = TimeAxis{"time", "", "", {0}};
  return m;
}

const lod::WorldFrame& frame(AxisKind z_kind) {
  static const lod::WorldFrame height(manifest(AxisKind::kHeight));
  static const lod::WorldFrame pressure(manifest(AxisKind::kPressure));
  return z_kind == AxisKind::kPressure ? pressure : height;
}

std::vector<std::uint8_t> bytes_of(std::string_view s) { return {s.begin(), s.end()}; }

void play(const lod::CameraPath& path, const lod::WorldFrame& f) {
  std::optional<lod::WorldCameraPath> world;
  try {
    world.emplace(path, f, "fuzz");
  } catch (const Error&) {
    return;
  }
  const double t0 = world->start_time(), t1 = world->end_time();
  for (double s : {-1.0, 0.0, 0.25, 0.5, 0.999, 1.0, 2.0}) {
    const lod::CameraPose pose = world->sample(t0 + s * (t1 - t0));
    if (!all_finite(pose.eye) || !all_finite(pose.target) ||
        !(pose.fov_deg > 0 && pose.fov_deg < 180)) {
      std::abort();
    }
    try {
      lod::pose_camera(pose, 16.0 / 9.0, f.domain());
    } catch (const Error&) {
      std::abort();  // a placed path always gives a valid camera
    }
  }
}

}  // namespace

std::vector<std::vector<std::uint8_t>> strielad_fuzz_seeds() {
  return {
      bytes_of(R"({"format_version": 1, "name": "approach from the south", "keyframes": [
        {"t": 0,  "eye": [9.5, 44.0, 120000], "target": [9.5, 51.0, 10500], "fov_deg": 45},
        {"t": 8,  "eye": [8.9, 48.5, 20000],  "target": [8.2, 50.0, 0]},
        {"t": 15, "eye": [7.9, 49.6, 4000],   "target": [7.6, 50.4, 0], "fov_deg": 60}]})"),
      bytes_of(R"({"keyframes":[{"t":-1e9,"eye":[9,48,850],"target":[9,51,1000]},{"t":1e9,"eye":[9,51,1e-300],"target":[9,48,5e-324],"fov_deg":179.999}]})"),
      bytes_of(R"({"keyframes":[{"t":0,"eye":[9,48,1000],"target":[9,51,1000]},{"t":1,"eye":[9,51,1000],"target":[9,48,1000]}]})"),
      bytes_of(R"({"format_version":2,"interpolation":"spline","keyframes":[{"t":0,"up":[0,0,1],"step":3,"eye":[1e999,0,0],"target":"x"}]})"),
      bytes_of("\xEF\xBB\xBF{\"name\":\"W\\u00f6lke \xE2\x82\xAC\",\"keyframes\":[{\"t\":0.5,\"eye\":[-0.0,90,-1e5],\"target\":[360,-90,0]}]}"),
  };
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  lod::CameraPath path;
  try {
    path = lod::parse_camera_path(text, "fuzz");
  } catch (const Error&) {
    return 0;
  }
  // A parsed path is valid: its canonical form must parse back to the same path and be
  // written identically again.
  try {
    const std::string canonical = lod::camera_path_to_json(path);
    const lod::CameraPath back = lod::parse_camera_path(canonical, "canonical");
    if (!(back == path) || lod::camera_path_to_json(back) != canonical) std::abort();
  } catch (const Error&) {
    std::abort();
  }
  play(path, frame(AxisKind::kHeight));
  play(path, frame(AxisKind::kPressure));
  return 0;
}
