// SPDX-License-Identifier: Apache-2.0
// Camera paths (formats/camera-path.md, lib/lod/camera_path.h): parsing, defaults, the
// canonical form, every rule a reader must reject (naming the JSON path), placement in a
// store's world frame, sampling, and the default fly-in path.
#include "lod/camera_path.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "lod/frustum.h"
#include "lod/lod_test_grids.h"
#include "support/expect_error.h"
#include "support/temp_dir.h"

namespace strielad::lod {
namespace {

using strielad::testing::expect_error;
using strielad::testing::TempDir;

// The example of formats/camera-path.md, read from the spec itself.
std::string spec_example() {
  std::ifstream in(std::string(STRIELAD_SOURCE_DIR) + "/formats/camera-path.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const auto begin = s.find("```json\n");
  const auto end = s.find("```", begin + 8);
  EXPECT_NE(begin, std::string::npos);
  return s.substr(begin + 8, end - begin - 8);
}

std::string one_keyframe(std::string_view body) {
  return fmt::format(R"({{"keyframes": [{{{}}}]}})", body);
}

constexpr std::string_view kTwo =
    R"({"keyframes": [{"t": 0, "eye": [9, 44, 120000], "target": [9.5, 51, 0]},
                      {"t": 10, "eye": [9.5, 50, 2000], "target": [9.5, 51, 0], "fov_deg": 60}]})";

void rejects(std::string_view json, std::initializer_list<std::string_view> parts,
             ErrorCode code = ErrorCode::kInvalidInput) {
  expect_error([&] { parse_camera_path(json, "path.json"); }, code, parts);
}

TEST(CameraPathTest, ParsesTheSpecExample) {
  const CameraPath p = parse_camera_path(spec_example(), "camera-path.md");
  EXPECT_EQ(p.name, "approach from the south");
  ASSERT_EQ(p.keyframes.size(), 3u);
  EXPECT_EQ(p.keyframes[0].eye, (Vec3{9.5, 44.0, 120000}));
  EXPECT_EQ(p.keyframes[1].fov_deg, kDefaultFovDeg);  // absent: 45
  EXPECT_EQ(p.keyframes[2].fov_deg, 60.0);
  EXPECT_EQ(p.keyframes[2].t, 15.0);
  // And it plays over a store of the region.
  const WorldFrame frame(testing::small_manifest());
  const WorldCameraPath world(p, frame, "camera-path.md");
  EXPECT_EQ(world.end_time(), 15.0);
}

TEST(CameraPathTest, CanonicalFormRoundTrips) {
  CameraPath p = parse_camera_path(kTwo, "two");
  EXPECT_EQ(p.name, "");
  p.name = "W\u00f6lkchen";
  p.keyframes[0].t = 0.1;
  p.keyframes[1].eye[2] = 1e-7;
  const std::string json = camera_path_to_json(p);
  EXPECT_EQ(json.rfind(R"({"format_version":1,"name":"W)", 0), 0u) << json;
  EXPECT_EQ(parse_camera_path(json, "canonical"), p);
  EXPECT_EQ(camera_path_to_json(parse_camera_path(json, "canonical")), json);
  // A single keyframe is a still camera; a leading byte order mark is ignored.
  const CameraPath one =
      parse_camera_path("\xEF\xBB\xBF" + one_keyframe(R"("t": -3, "eye": [1,2,3], "target": [1,2,0])"), "one");
  EXPECT_EQ(one.keyframes.size(), 1u);
}

TEST(CameraPathTest, RejectsWhatTheFormatRejects) {
  rejects("", {"path.json", "not valid JSON"});
  rejects("[1, 2]", {"path.json", "a JSON object at the top level"});
  rejects(R"({"keyframes": [], "keyframes": []})", {"key 'keyframes' appears twice"});
  rejects(R"({"keyframes": [[[[[[[[[1]]]]]]]]]})", {"nest deeper than 8"});
  rejects(R"({"keyframes": [{"t": 0, "eye": [1,2,3], "target": [1,2,0], "roll": 3}]})",
          {"keyframes[0].roll", "unknown key 'roll'", "t, eye, target, fov_deg"});
  rejects(R"({"frames": []})", {"frames: unknown key", "format_version, name, keyframes"});
  rejects(R"({"interpolation": "catmull-rom", "keyframes": []})",
          {"interpolation", "reserved for a later version"});
  rejects(one_keyframe(R"("t": 0, "eye": [1,2,3], "target": [1,2,0], "up": [0,0,1])"),
          {"keyframes[0].up", "reserved"});
  rejects(R"({"name": "x"})", {"missing required key 'keyframes'"});
  rejects(R"({"keyframes": []})", {"keyframes: needs at least one keyframe"});
  rejects(R"({"keyframes": {}})", {"keyframes: expected an array"});
  rejects(R"({"keyframes": [3]})", {"keyframes[0]: expected an object"});
  rejects(one_keyframe(R"("eye": [1,2,3], "target": [1,2,0])"), {"keyframes[0]", "missing required key 't'"});
  rejects(one_keyframe(R"("t": 0, "target": [1,2,0])"), {"missing required key 'eye'"});
  rejects(one_keyframe(R"("t": 0, "eye": [1,2,3])"), {"missing required key 'target'"});
  rejects(one_keyframe(R"("t": "0", "eye": [1,2,3], "target": [1,2,0])"),
          {"keyframes[0].t: expected a number, got string \"0\""});
  rejects(one_keyframe(R"("t": null, "eye": [1,2,3], "target": [1,2,0])"), {"keyframes[0].t", "null"});
  rejects(one_keyframe(R"("t": 0, "eye": [1,2], "target": [1,2,0])"),
          {"keyframes[0].eye: expected an array of three numbers"});
  rejects(one_keyframe(R"("t": 0, "eye": [1,2,3], "target": [1,2,"x"])"), {"keyframes[0].target[2]"});
  rejects(one_keyframe(R"("t": 0, "eye": [1,2,1e999], "target": [1,2,0])"),
          {"keyframes[0].eye[2]", "not a finite number"});
  rejects(one_keyframe(R"("t": 2e9, "eye": [1,2,3], "target": [1,2,0])"), {"keyframes[0].t", "outside"});
  rejects(one_keyframe(R"("t": 0, "eye": [1,2,3], "target": [1,2,3])"), {"keyframes[0].target", "equals eye"});
  rejects(one_keyframe(R"("t": 0, "eye": [1,2,3], "target": [1,2,0], "fov_deg": 0)"),
          {"keyframes[0].fov_deg", "(0, 180)"});
  rejects(one_keyframe(R"("t": 0, "eye": [1,2,3], "target": [1,2,0], "fov_deg": 180)"),
          {"keyframes[0].fov_deg"});
  rejects(R"({"keyframes": [{"t": 1, "eye": [1,2,3], "target": [1,2,0]},
                            {"t": 1, "eye": [1,2,4], "target": [1,2,0]}]})",
          {"keyframes[1].t", "increase strictly"});
  rejects(R"({"keyframes": [{"t": 1, "eye": [1,2,3], "target": [1,2,0]},
                            {"t": 0.5, "eye": [1,2,4], "target": [1,2,0]}]})",
          {"keyframes[1].t"});
  rejects(R"({"name": 5, "keyframes": []})", {"name: expected a string"});
  rejects(fmt::format(R"({{"name": "{}", "keyframes": [{{"t": 0, "eye": [1,2,3], "target": [1,2,0]}}]}})",
                      std::string(257, 'n')),
          {"name: has 257 bytes"});
  rejects(R"({"format_version": 1.0, "keyframes": []})", {"format_version: expected an integer"});
  rejects(R"({"format_version": 0, "keyframes": []})", {"format_version", ">= 1"});
  rejects(R"({"format_version": 2, "up": 1})", {"format_version 2 is newer than this reader (max 1)"},
          ErrorCode::kVersionTooNew);
  rejects(std::string(kMaxCameraPathBytes + 1, ' '), {"more than the limit"});
}

TEST(CameraPathTest, ValidationOfPathsBuiltInCode) {
  CameraPath p;
  expect_error([&] { validate_camera_path(p, "built"); }, ErrorCode::kInvalidInput,
               {"built: keyframes: needs at least one"});
  p.keyframes.push_back(Keyframe{0, {1, 2, 3}, {1, 2, 0}, 45});
  p.name = "\xff";
  expect_error([&] { camera_path_to_json(p); }, ErrorCode::kInvalidInput, {"name", "UTF-8"});
  p.name = "";
  p.keyframes[0].eye[1] = NAN;
  expect_error([&] { validate_camera_path(p, "built"); }, ErrorCode::kInvalidInput,
               {"keyframes[0].eye[1]", "finite"});
}

TEST(CameraPathTest, SamplesLinearlyInWorldSpaceAndClampsAtTheEnds) {
  const WorldFrame frame(testing::small_manifest());
  const CameraPath p = parse_camera_path(kTwo, "two");
  const WorldCameraPath w(p, frame, "two");
  EXPECT_EQ(w.start_time(), 0.0);
  EXPECT_EQ(w.end_time(), 10.0);
  const Vec3 e0 = frame.to_world(p.keyframes[0].eye), e1 = frame.to_world(p.keyframes[1].eye);
  const CameraPose mid = w.sample(2.5);
  const Vec3 want = lerp(e0, e1, 0.25);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(mid.eye[a], want[a], 1e-9);
  EXPECT_DOUBLE_EQ(mid.fov_deg, 45 + 0.25 * 15);
  EXPECT_EQ(w.sample(-100).eye, e0);
  EXPECT_EQ(w.sample(0).eye, e0);
  EXPECT_EQ(w.sample(10).eye, e1);
  EXPECT_EQ(w.sample(1e300).eye, e1);
  EXPECT_EQ(w.sample(INFINITY).fov_deg, 60.0);
  expect_error([&] { w.sample(NAN); }, ErrorCode::kInvalidArgument, {"NaN"});
  // A pose becomes a valid camera.
  validate_camera(pose_camera(mid, 16.0 / 9.0, frame.domain()));
}

TEST(CameraPathTest, PressurePathsMoveEvenlyInHeight) {
  const WorldFrame frame(testing::geographic_manifest(9, 9, {1000, 850, 500, 200, 100},
                                                     AxisKind::kPressure, "hPa"));
  const CameraPath p = parse_camera_path(
      R"({"keyframes": [{"t": 0, "eye": [9, 48, 1000], "target": [9, 51, 1000]},
                        {"t": 1, "eye": [9, 48, 100], "target": [9, 51, 1000]}]})",
      "p");
  const WorldCameraPath w(p, frame, "p");
  const double z0 = frame.vertical_to_world(1000), z1 = frame.vertical_to_world(100);
  EXPECT_NEAR(w.sample(0.5).eye[2], 0.5 * (z0 + z1), 1e-9);
  EXPECT_NE(frame.world_to_vertical(w.sample(0.5).eye[2]), 550.0);  // not halfway in hPa
}

TEST(CameraPathTest, PlacementRejectsPointsTheStoreCannotPlace) {
  const WorldFrame pressure(testing::geographic_manifest(5, 5, {1000, 500, 100},
                                                        AxisKind::kPressure, "hPa"));
  const CameraPath negative = parse_camera_path(
      R"({"keyframes": [{"t": 0, "eye": [9, 48, 500], "target": [9, 51, 1000]},
                        {"t": 1, "eye": [9, 48, -5], "target": [9, 51, 1000]}]})",
      "p");
  expect_error([&] { WorldCameraPath(negative, pressure, "p.json"); }, ErrorCode::kInvalidInput,
               {"p.json: keyframes[1].eye[2]", "pressure -5", "> 0"});

  const WorldFrame heights(testing::small_manifest());
  const CameraPath far = parse_camera_path(one_keyframe(R"("t": 0, "eye": [1e5, 50, 0], "target": [9, 50, 0])"), "f");
  expect_error([&] { WorldCameraPath(far, heights, "f.json"); }, ErrorCode::kInvalidInput,
               {"keyframes[0].eye[0]", "km from the domain centre"});
  const CameraPath swap = parse_camera_path(
      R"({"keyframes": [{"t": 0, "eye": [9, 48, 1000], "target": [9, 51, 1000]},
                        {"t": 1, "eye": [9, 51, 1000], "target": [9, 48, 1000]}]})",
      "s");
  expect_error([&] { WorldCameraPath(swap, heights, "s.json"); }, ErrorCode::kInvalidInput,
               {"s.json: keyframes[1]", "comes within"});
}

void check_fly_in(const format::Manifest& m) {
  const WorldFrame frame(m);
  const CameraPath path = default_fly_in_path(m, 20.0);
  ASSERT_GE(path.keyframes.size(), 2u);
  EXPECT_EQ(path.keyframes.front().t, 0.0);
  EXPECT_EQ(path.keyframes.back().t, 20.0);
  // It survives the file format and plays over the store.
  const CameraPath back = parse_camera_path(camera_path_to_json(path), "fly-in");
  const WorldCameraPath w(back, frame, "fly-in");
  const WorldBox& d = frame.domain();

  // The start sees the whole domain.
  const Camera start = pose_camera(w.sample(0), 16.0 / 9.0, d);
  const Frustum fr = view_frustum(start);
  for (int i = 0; i < 8; ++i) {
    const Vec3 corner{(i & 1) ? d.hi[0] : d.lo[0], (i & 2) ? d.hi[1] : d.lo[1],
                      (i & 4) ? d.hi[2] : d.lo[2]};
    EXPECT_TRUE(fr.contains(corner)) << "corner " << i;
  }
  // The eye approaches all the way.
  double previous = INFINITY;
  for (double t = 0; t <= 20; t += 0.5) {
    const CameraPose pose = w.sample(t);
    const double distance = length(sub(pose.target, pose.eye));
    EXPECT_LT(distance, previous) << t;
    previous = distance;
  }
  // It ends low and oblique over the centre: inside the domain, below its top, looking
  // down at 15 to 35 degrees.
  const CameraPose end = w.sample(20);
  EXPECT_TRUE(d.contains(end.eye));
  const Vec3 view = sub(end.target, end.eye);
  const double down = std::atan2(-view[2], std::hypot(view[0], view[1])) * 180 / std::numbers::pi;
  EXPECT_GT(down, 15);
  EXPECT_LT(down, 35);
  EXPECT_NEAR(end.target[0], d.center()[0], 1e-6);
  EXPECT_NEAR(end.target[1], d.center()[1], 1e-6);
}

TEST(CameraPathTest, DefaultFlyInGoesFromTheWholeDomainToALowObliqueView) {
  check_fly_in(testing::paper_manifest());
  check_fly_in(testing::geographic_manifest(40, 30, {1000, 850, 500, 200, 100}, AxisKind::kPressure, "hPa"));
  format::Manifest metric = testing::small_manifest();
  metric.x.units = "m";
  metric.x.values = testing::linspace(-50000, 50000, metric.x.size());
  metric.y.units = "m";
  metric.y.values = testing::linspace(0, 80000, metric.y.size());
  check_fly_in(metric);
  expect_error([] { default_fly_in_path(testing::small_manifest(), 0.0); },
               ErrorCode::kInvalidArgument, {"duration"});
}

TEST(CameraPathTest, LoadsFilesAndNamesThem) {
  const TempDir dir;
  const auto file = dir / "fly.json";
  std::ofstream(file) << kTwo;
  EXPECT_EQ(load_camera_path_file(file), parse_camera_path(kTwo, "x"));
  expect_error([&] { load_camera_path_file(dir / "missing.json"); }, ErrorCode::kNotFound,
               {"missing.json"});
  std::ofstream(dir / "bad.json") << R"({"keyframes": [{"t": 0}]})";
  expect_error([&] { load_camera_path_file(dir / "bad.json"); }, ErrorCode::kInvalidInput,
               {"bad.json: keyframes[0]", "'eye'"});
}

}  // namespace
}  // namespace strielad::lod
