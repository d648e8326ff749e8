// SPDX-License-Identifier: Apache-2.0
// Scene format version 2 (formats/scene.md): slices, terrain, sun and trajectories are
// parsed, validated with errors naming the path, written in canonical form, and
// resolved against a store; a version-1 scene cannot use them.
#include <gtest/gtest.h>

#include <string>

#include "format/manifest.h"
#include "scene/scene.h"
#include "support/expect_error.h"

namespace strielad {
namespace {

using testing::expect_error;

constexpr std::string_view kExample = R"({
  "format_version": 2,
  "subvolumes": [{"id": 1, "limits": [{"var": "clw", "min": 1e-5}]}],
  "slices": [
    {"id": 1, "name": "500 m", "axis": "height", "value": 500, "var": "ta",
     "colormap": "coolwarm", "range": [250, 300]},
    {"id": 2, "level": {"var": "pres", "value": 50000}, "var": "ta"}
  ],
  "terrain": {"dem": "dem.nc", "var": "HSURF", "image": "map.tif"},
  "sun": {"elevation": 30, "azimuth": 180},
  "trajectories": {"file": "tracks.csv", "minutes": 5}
})";

std::string v2(std::string_view body) {
  return fmt::format(R"({{"format_version": 2, "subvolumes": [{{"id": 1, "limits": [{{"var": "clw", "min": 0}}]}}], {}}})", body);
}

void expect_invalid(const std::string& json, std::initializer_list<std::string_view> parts) {
  SCOPED_TRACE(json);
  expect_error([&] { parse_scene(json, "scene.json"); }, ErrorCode::kInvalidInput, parts);
}

TEST(SceneVersion2KeysTest, ParsesEveryNewKey) {
  const Scene s = parse_scene(kExample, "scene.json");
  ASSERT_EQ(s.slices.size(), 2u);
  EXPECT_EQ(s.slices[0], (Slice{1, "500 m", "height", "", 500.0, "ta", "coolwarm", AxisRange{250, 300}}));
  EXPECT_EQ(s.slices[1], (Slice{2, "", "", "pres", 50000.0, "ta", "viridis", std::nullopt}));
  EXPECT_TRUE(s.slices[1].is_level());
  EXPECT_EQ(s.terrain, (Terrain{"dem.nc", "HSURF", "map.tif"}));
  EXPECT_EQ(s.sun, (Sun{false, 30, 180}));
  EXPECT_EQ(s.trajectories, (Trajectories{"tracks.csv", 5}));
  const Scene t = parse_scene(v2(R"("sun": {"mode": "time"}, "trajectories": {"file": "t.nc"})"), "s");
  EXPECT_EQ(t.sun, (Sun{}));
  EXPECT_EQ(t.trajectories->minutes, 2.0);
}

TEST(SceneVersion2KeysTest, CanonicalFormRoundTripsAndDeclaresTheVersionItNeeds) {
  const Scene s = parse_scene(kExample, "scene.json");
  const std::string canonical = scene_to_json(s);
  EXPECT_EQ(parse_scene(canonical, "canonical"), s);
  EXPECT_EQ(scene_to_json(parse_scene(canonical, "canonical")), canonical);
  EXPECT_EQ(canonical,
            R"({"format_version":2,"time":0,"subvolumes":[{"id":1,"name":"","limits":[{"var":"clw","min":1e-05}]}],)"
            R"("attributes":[],"slices":[{"id":1,"name":"500 m","axis":"height","value":500.0,"var":"ta",)"
            R"("colormap":"coolwarm","range":[250.0,300.0]},{"id":2,"name":"","level":{"var":"pres","value":50000.0},)"
            R"("var":"ta","colormap":"viridis"}],"terrain":{"dem":"dem.nc","var":"HSURF","image":"map.tif"},)"
            R"("sun":{"elevation":30.0,"azimuth":180.0},"trajectories":{"file":"tracks.csv","minutes":5.0}})");
  // Without version-2 keys the canonical form stays version 1, readable by old readers.
  Scene plain = s;
  plain.slices.clear();
  plain.terrain.reset();
  plain.sun.reset();
  plain.trajectories.reset();
  EXPECT_EQ(scene_to_json(plain).rfind(R"({"format_version":1,)", 0), 0u);
}

TEST(SceneVersion2KeysTest, NewKeysNeedFormatVersion2) {
  for (const char* key : {"slices", "terrain", "sun", "trajectories"}) {
    const std::string json = fmt::format(
        R"({{"subvolumes": [{{"id": 1, "limits": [{{"var": "a", "min": 0}}]}}], "{}": {{}}}})", key);
    expect_invalid(json, {key, "added in format_version 2", "declares 1"});
  }
  expect_error([] { parse_scene(R"({"format_version": 5, "subvolumes": []})", "s"); },
               ErrorCode::kVersionTooNew, {"format_version 5 is newer than this reader (max 4)"});
  expect_invalid(v2(R"("advection": {})"), {"advection", "reserved for a later version"});
}

TEST(SceneVersion2KeysTest, SliceRejections) {
  expect_invalid(v2(R"("slices": {})"), {"slices", "array"});
  expect_invalid(v2(R"("slices": [{"axis": "lat", "value": 1, "var": "ta"}])"), {"slices[0]", "id"});
  expect_invalid(v2(R"("slices": [{"id": 0, "axis": "lat", "value": 1, "var": "ta"}])"), {"slices[0].id"});
  expect_invalid(v2(R"("slices": [{"id": 65536, "axis": "lat", "value": 1, "var": "ta"}])"), {"slices[0].id"});
  expect_invalid(v2(R"("slices": [{"id": 1, "value": 1, "var": "ta"}])"), {"slices[0]", "exactly one of 'axis'"});
  expect_invalid(v2(R"("slices": [{"id": 1, "axis": "lat", "level": {"var": "p", "value": 1}, "var": "ta"}])"),
                 {"slices[0]", "exactly one of"});
  expect_invalid(v2(R"("slices": [{"id": 1, "axis": "lat", "var": "ta"}])"), {"slices[0]", "needs 'value'"});
  expect_invalid(v2(R"("slices": [{"id": 1, "axis": "lat", "value": "1", "var": "ta"}])"), {"slices[0].value"});
  expect_invalid(v2(R"("slices": [{"id": 1, "level": {"var": "p"}, "var": "ta"}])"), {"slices[0].level", "value"});
  expect_invalid(v2(R"("slices": [{"id": 1, "level": {"var": "p", "value": 1}, "value": 2, "var": "ta"}])"),
                 {"slices[0].value", "inside 'level'"});
  expect_invalid(v2(R"("slices": [{"id": 1, "level": {"var": "p", "value": 1, "x": 0}, "var": "ta"}])"),
                 {"slices[0].level", "x"});
  expect_invalid(v2(R"("slices": [{"id": 1, "axis": "lat", "value": 1}])"), {"slices[0]", "var"});
  expect_invalid(v2(R"("slices": [{"id": 1, "axis": "", "value": 1, "var": "ta"}])"), {"slices[0].axis"});
  expect_invalid(v2(R"("slices": [{"id": 1, "axis": "lat", "value": 1, "var": "ta", "colormap": "jet"}])"),
                 {"slices[0].colormap", "'jet' is not a colour map", "viridis, magma, coolwarm, greys, turbo"});
  expect_invalid(v2(R"("slices": [{"id": 1, "axis": "lat", "value": 1, "var": "ta", "range": [2, 2]}])"),
                 {"slices[0].range", "less than"});
  expect_invalid(v2(R"("slices": [{"id": 1, "axis": "lat", "value": 1, "var": "ta", "range": [2]}])"),
                 {"slices[0].range", "two numbers"});
  expect_invalid(v2(R"("slices": [{"id": 1, "axis": "lat", "value": 1, "var": "ta", "style": 1}])"),
                 {"slices[0]", "style"});
  expect_invalid(v2(R"("slices": [{"id": 3, "axis": "lat", "value": 1, "var": "ta"},
                                  {"id": 3, "axis": "lon", "value": 1, "var": "ta"}])"),
                 {"slices[1].id", "already used by slices[0]"});
  std::string many = R"("slices": [)";
  for (int i = 1; i <= 17; ++i) {
    many += fmt::format(R"({}{{"id": {}, "axis": "lat", "value": 1, "var": "ta"}})", i > 1 ? "," : "", i);
  }
  expect_invalid(v2(many + "]"), {"slices", "17 slices, more than the limit of 16"});
}

TEST(SceneVersion2KeysTest, TerrainSunAndTrajectoryRejections) {
  expect_invalid(v2(R"("terrain": {})"), {"terrain", "dem"});
  expect_invalid(v2(R"("terrain": {"dem": ""})"), {"terrain.dem"});
  expect_invalid(v2(R"("terrain": {"dem": "a", "tiles": 3})"), {"terrain", "tiles"});
  expect_invalid(v2(R"("sun": {"mode": "noon"})"), {"sun.mode", "must be \"time\""});
  expect_invalid(v2(R"("sun": {"mode": "time", "elevation": 3, "azimuth": 4})"), {"sun", "not both"});
  expect_invalid(v2(R"("sun": {"elevation": 3})"), {"sun", "both 'elevation' and 'azimuth'"});
  expect_invalid(v2(R"("sun": {"elevation": 91, "azimuth": 0})"), {"sun.elevation", "[-90, 90]"});
  expect_invalid(v2(R"("sun": {"elevation": 0, "azimuth": 361})"), {"sun.azimuth", "[0, 360]"});
  expect_invalid(v2(R"("trajectories": {"minutes": 2})"), {"trajectories", "file"});
  expect_invalid(v2(R"("trajectories": {"file": "t.csv", "minutes": 0})"), {"trajectories.minutes", "greater than 0"});
  expect_invalid(v2(R"("trajectories": {"file": "t.csv", "minutes": -1})"), {"trajectories.minutes"});
}

format::Manifest manifest() {
  format::Manifest m;
  m.x = Axis{"lon", AxisKind::kLongitude, "degrees_east", "longitude", "", "", {4.5, 5.5, 9.5}};
  m.y = Axis{"lat", AxisKind::kLatitude, "degrees_north", "latitude", "", "", {54.5, 51.0, 47.5}};
  m.z = Axis{"height", AxisKind::kHeight, "m", "height", "", "up", {21000.0, 5000.0, 20.0}};
  m.time = TimeAxis{"time", "seconds since 2013-04-26 00:00:00", "standard", {0, 300}};
  for (const char* name : {"clw", "pres", "ta", "ua"}) {
    format::StoreVariable v;
    v.name = name;
    m.variables.push_back(v);
  }
  return m;
}

TEST(SceneVersion2KeysTest, ResolvesSlicesAgainstTheStore) {
  const ResolvedScene r = resolve_scene(parse_scene(kExample, "scene.json"), manifest(), "scene.json");
  ASSERT_EQ(r.slices.size(), 2u);
  EXPECT_EQ(r.slices[0].axis, 2);
  EXPECT_EQ(r.slices[0].variable, 2u);
  EXPECT_EQ(r.slices[0].value, 500.0);
  EXPECT_EQ(r.slices[0].colormap, "coolwarm");
  EXPECT_TRUE(r.slices[1].is_level());
  EXPECT_EQ(r.slices[1].level_variable, 1u);
  // Slice variables are needed, nothing else is.
  EXPECT_EQ(r.needed_variables, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(SceneVersion2KeysTest, ResolutionRejectsWhatTheStoreLacks) {
  const auto resolve = [](std::string_view slice) {
    resolve_scene(parse_scene(v2(fmt::format(R"("slices": [{}])", slice)), "s"), manifest(), "scene.json");
  };
  expect_error([&] { resolve(R"({"id": 1, "axis": "alt", "value": 1, "var": "ta"})"); },
               ErrorCode::kNotFound, {"scene.json", "slices[0].axis", "'alt'", "x lon, y lat, z height"});
  expect_error([&] { resolve(R"({"id": 1, "axis": "lat", "value": 50, "var": "tb"})"); },
               ErrorCode::kNotFound, {"slices[0].var", "'tb'", "clw, pres, ta, ua"});
  expect_error([&] { resolve(R"({"id": 1, "level": {"var": "p", "value": 5}, "var": "ta"})"); },
               ErrorCode::kNotFound, {"slices[0].level.var", "'p'"});
  expect_error([&] { resolve(R"({"id": 1, "axis": "height", "value": 10, "var": "ta"})"); },
               ErrorCode::kInvalidInput, {"slices[0].value", "10 lies outside the store's height axis [20, 21000]"});
  // The extent's ends are inside (descending axis included).
  resolve(R"({"id": 1, "axis": "lat", "value": 54.5, "var": "ta"})");
  resolve(R"({"id": 1, "axis": "height", "value": 20, "var": "ta"})");
}

}  // namespace
}  // namespace strielad
