// SPDX-License-Identifier: Apache-2.0
// Resolving a scene against a store's manifest (formats/scene.md, "Resolution against a
// store"): names become indices, open bounds infinities, and what the store lacks is
// reported with what it has.
#include <gtest/gtest.h>

#include <limits>

#include "format/manifest.h"
#include "scene/scene.h"
#include "support/expect_error.h"

namespace strielad {
namespace {

using testing::expect_error;
constexpr double kInf = std::numeric_limits<double>::infinity();

// lon ascending, lat descending (north to south), height stored top to bottom.
format::Manifest sample_manifest() {
  format::Manifest m;
  m.x = Axis{"lon", AxisKind::kLongitude, "degrees_east", "longitude", "", "", {4.5, 5.5, 9.5, 14.5}};
  m.y = Axis{"lat", AxisKind::kLatitude, "degrees_north", "latitude", "", "", {54.5, 51.0, 47.5}};
  m.z = Axis{"height", AxisKind::kHeight, "m", "height", "", "up", {21000.0, 5000.0, 20.0}};
  m.time = TimeAxis{"time", "seconds since 2013-04-26 00:00:00", "standard", {0, 300, 600, 900}};
  for (const char* name : {"clw", "cli", "qr", "ta", "ua"}) {
    format::StoreVariable v;
    v.name = name;
    m.variables.push_back(v);
  }
  return m;
}

constexpr std::string_view kSpecExample = R"({
  "time": 3,
  "subvolumes": [
    {"id": 1, "name": "cloud ice",
     "limits": [{"var": "cli", "min": 1e-6}],
     "domain": {"lon": [5.0, 15.0], "lat": [47.0, 55.0], "height": [0, 12000]}},
    {"id": 2, "name": "rain in warm air",
     "limits": [{"var": "qr", "min": 1e-5}, {"var": "ta", "min": 273.15, "max": 320}]},
    {"id": 3, "name": "column", "domain": {"lat": [50.0, 50.3]}}
  ],
  "attributes": ["ua", "ta"]
})";

ResolvedScene resolve(std::string_view json) {
  return resolve_scene(parse_scene(json, "scene.json"), sample_manifest(), "scene.json");
}

TEST(SceneResolveTest, ResolvesTheSpecExample) {
  const ResolvedScene r = resolve(kSpecExample);
  EXPECT_EQ(r.time, 3u);
  ASSERT_EQ(r.subvolumes.size(), 3u);

  const ResolvedSubVolume& ice = r.subvolumes[0];
  EXPECT_EQ(ice.id, 1u);
  EXPECT_EQ(ice.name, "cloud ice");
  EXPECT_EQ(ice.limits, (std::vector<ResolvedLimit>{{1, 1e-6, kInf}}));
  EXPECT_EQ(ice.box[0], (AxisRange{5.0, 15.0}));    // x = lon
  EXPECT_EQ(ice.box[1], (AxisRange{47.0, 55.0}));   // y = lat, descending axis
  EXPECT_EQ(ice.box[2], (AxisRange{0, 12000}));     // z = height

  const ResolvedSubVolume& rain = r.subvolumes[1];
  EXPECT_EQ(rain.limits, (std::vector<ResolvedLimit>{{2, 1e-5, kInf}, {3, 273.15, 320}}));
  for (const AxisRange& range : rain.box) EXPECT_EQ(range, (AxisRange{-kInf, kInf}));

  const ResolvedSubVolume& column = r.subvolumes[2];
  EXPECT_TRUE(column.limits.empty());
  EXPECT_EQ(column.box[0], (AxisRange{-kInf, kInf}));
  EXPECT_EQ(column.box[1], (AxisRange{50.0, 50.3}));

  EXPECT_EQ(r.attributes, (std::vector<std::uint32_t>{4, 3}));         // scene order
  EXPECT_EQ(r.needed_variables, (std::vector<std::uint32_t>{1, 2, 3, 4}));  // sorted, distinct
}

TEST(SceneResolveTest, OpenBoundsBecomeInfinities) {
  const ResolvedScene r = resolve(R"({"subvolumes": [{"id": 9, "limits": [{"var": "clw", "max": 0.5}, {"var": "ta", "min": 250}]}]})");
  EXPECT_EQ(r.subvolumes[0].limits, (std::vector<ResolvedLimit>{{0, -kInf, 0.5}, {3, 250, kInf}}));
  EXPECT_EQ(r.needed_variables, (std::vector<std::uint32_t>{0, 3}));
  EXPECT_TRUE(r.attributes.empty());
}

TEST(SceneResolveTest, UnknownVariableListsTheStoresVariables) {
  expect_error([] { resolve(R"({"subvolumes": [{"id": 1, "limits": [{"var": "clw", "min": 0}]},
                                                {"id": 2, "limits": [{"var": "ta", "min": 0}, {"var": "qx", "min": 0}]}]})"); },
               ErrorCode::kNotFound,
               {"scene.json: subvolumes[1].limits[1].var: variable 'qx' is not in the store",
                "(it has: clw, cli, qr, ta, ua)"});
}

TEST(SceneResolveTest, UnknownAttributeListsTheStoresVariables) {
  expect_error([] { resolve(R"({"subvolumes": [{"id": 1, "limits": [{"var": "clw", "min": 0}]}], "attributes": ["ta", "TA"]})"); },
               ErrorCode::kNotFound,
               {"scene.json: attributes[1]: variable 'TA' is not in the store", "clw, cli, qr, ta, ua"});
}

TEST(SceneResolveTest, UnknownAxisListsTheStoresAxes) {
  expect_error([] { resolve(R"({"subvolumes": [{"id": 1, "domain": {"lon": [5, 6], "longitude": [5, 6]}}]})"); },
               ErrorCode::kNotFound,
               {"scene.json: subvolumes[0].domain.longitude: axis 'longitude' is not an axis of the store",
                "(its axes: x lon, y lat, z height)"});
}

TEST(SceneResolveTest, TimeStepOutOfRange) {
  expect_error([] { resolve(R"({"time": 4, "subvolumes": [{"id": 1, "domain": {"lon": [5, 6]}}]})"); },
               ErrorCode::kNotFound,
               {"scene.json: time: time step 4 is out of range: the store has 4 time steps (0..3)"});
  format::Manifest empty = sample_manifest();
  empty.time.values.clear();
  expect_error([&] { resolve_scene(parse_scene(R"({"subvolumes": [{"id": 1, "domain": {"lon": [5, 6]}}]})", "s"), empty, "s"); },
               ErrorCode::kNotFound, {"s: time: time step 0 is out of range: the store has no time steps"});
}

TEST(SceneResolveTest, DomainOutsideTheAxisExtent) {
  expect_error([] { resolve(R"({"subvolumes": [{"id": 1, "domain": {"height": [0, 12]}}]})"); },
               ErrorCode::kInvalidInput,
               {"scene.json: subvolumes[0].domain.height: [0, 12] lies outside the store's height axis [20, 21000]"});
  expect_error([] { resolve(R"({"subvolumes": [{"id": 1, "domain": {"lat": [55, 60]}}]})"); },
               ErrorCode::kInvalidInput,
               {"subvolumes[0].domain.lat: [55, 60] lies outside the store's lat axis [47.5, 54.5]"});
}

TEST(SceneResolveTest, DomainTouchingOrCoveringTheExtentIsAccepted) {
  const ResolvedScene r = resolve(R"({"subvolumes": [
      {"id": 1, "domain": {"height": [0, 20]}},
      {"id": 2, "domain": {"lat": [54.5, 54.5]}},
      {"id": 3, "domain": {"lon": [-180, 180]}}]})");
  EXPECT_EQ(r.subvolumes[0].box[2], (AxisRange{0, 20}));     // not clamped
  EXPECT_EQ(r.subvolumes[1].box[1], (AxisRange{54.5, 54.5}));
  // A full turn of longitude is the whole axis, whatever its convention.
  EXPECT_EQ(r.subvolumes[2].box[0], (AxisRange{-kInf, kInf}));
  EXPECT_TRUE(r.needed_variables.empty());  // box-only sub-volumes read no variable
}

TEST(SceneResolveTest, ValidatesScenesBuiltInCode) {
  Scene s;
  expect_error([&] { resolve_scene(s, sample_manifest(), "panel"); }, ErrorCode::kInvalidInput,
               {"panel: subvolumes: a scene needs at least one sub-volume"});
  s.subvolumes.push_back(SubVolume{1, "", {Limit{"ta", 300, 200}}, {}});
  expect_error([&] { resolve_scene(s, sample_manifest(), "panel"); }, ErrorCode::kInvalidInput,
               {"panel: subvolumes[0].limits[0]: min 300 is greater than max 200"});
  s.subvolumes[0].limits[0] = Limit{"ta", 200, 300};
  s.subvolumes.push_back(SubVolume{1, "", {}, {{"lon", AxisRange{5, 6}}}});
  expect_error([&] { resolve_scene(s, sample_manifest(), "panel"); }, ErrorCode::kInvalidInput,
               {"panel: subvolumes[1].id: id 1 is already used by subvolumes[0]"});
  s.subvolumes[1].id = 2;
  EXPECT_EQ(resolve_scene(s, sample_manifest(), "panel").subvolumes.size(), 2u);
}

TEST(SceneResolveTest, SameVariableInLimitsAndAttributesIsNeededOnce) {
  const ResolvedScene r = resolve(R"({"subvolumes": [
      {"id": 1, "limits": [{"var": "ta", "min": 250}, {"var": "ta", "max": 273.15}]},
      {"id": 2, "limits": [{"var": "ta", "min": 300}]}], "attributes": ["ta"]})");
  EXPECT_EQ(r.needed_variables, (std::vector<std::uint32_t>{3}));
  EXPECT_EQ(r.subvolumes[0].limits.size(), 2u);
}

}  // namespace
}  // namespace strielad
