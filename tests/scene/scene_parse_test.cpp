// SPDX-License-Identifier: Apache-2.0
// Scene JSON (formats/scene.md): parsing, defaults, the canonical form, and every rule a
// reader must reject, each error naming the path of the offending value.
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <string>

#include "support/expect_error.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using testing::expect_error;

constexpr std::string_view kSpecExample = R"({
  "format_version": 1,
  "time": 0,
  "subvolumes": [
    {"id": 1, "name": "cloud ice",
     "limits": [{"var": "cli", "min": 1e-6}],
     "domain": {"lon": [5.0, 15.0], "lat": [47.0, 55.0], "height": [0, 12000]}},
    {"id": 2, "name": "rain in warm air",
     "limits": [{"var": "qr", "min": 1e-5}, {"var": "ta", "min": 273.15, "max": 320}]},
    {"id": 3, "name": "column above the radar",
     "domain": {"lon": [7.0, 7.5], "lat": [50.0, 50.3]}}
  ],
  "attributes": ["ta", "ua"]
})";

// A valid scene with `sub` as its only sub-volume's body (after the id).
std::string one_subvolume(std::string_view sub) {
  return fmt::format(R"({{"subvolumes": [{{"id": 1, {}}}]}})", sub);
}

std::string with_limit(std::string_view limit) {
  return one_subvolume(fmt::format(R"("limits": [{}])", limit));
}

void expect_invalid(const std::string& json, std::initializer_list<std::string_view> parts) {
  SCOPED_TRACE(json.size() < 300 ? json : json.substr(0, 300));
  std::vector<std::string_view> all{"scene.json"};
  all.insert(all.end(), parts.begin(), parts.end());
  try {
    parse_scene(json, "scene.json");
    ADD_FAILURE() << "no error thrown";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kInvalidInput) << e.what();
    for (std::string_view part : all) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
          << "message lacks \"" << part << "\": " << e.what();
    }
  }
}

TEST(SceneParseTest, ParsesTheSpecExample) {
  const Scene s = parse_scene(kSpecExample, "scene.json");
  EXPECT_EQ(s.time, 0u);
  ASSERT_EQ(s.subvolumes.size(), 3u);
  const SubVolume& ice = s.subvolumes[0];
  EXPECT_EQ(ice.id, 1u);
  EXPECT_EQ(ice.name, "cloud ice");
  ASSERT_EQ(ice.limits.size(), 1u);
  EXPECT_EQ(ice.limits[0], (Limit{"cli", 1e-6, std::nullopt}));
  ASSERT_EQ(ice.domain.size(), 3u);
  EXPECT_EQ(ice.domain.at("lon"), (AxisRange{5.0, 15.0}));
  EXPECT_EQ(ice.domain.at("height"), (AxisRange{0, 12000}));
  const SubVolume& rain = s.subvolumes[1];
  EXPECT_EQ(rain.limits[1], (Limit{"ta", 273.15, 320.0}));
  EXPECT_TRUE(rain.domain.empty());
  EXPECT_TRUE(s.subvolumes[2].limits.empty());
  EXPECT_EQ(s.attributes, (std::vector<std::string>{"ta", "ua"}));
}

TEST(SceneParseTest, OptionalKeysTakeTheirDefaults) {
  const Scene s = parse_scene(R"({"subvolumes": [{"id": 7, "limits": [{"var": "clw", "max": 0}]}]})",
                              "scene.json");
  EXPECT_EQ(s.time, 0u);
  EXPECT_TRUE(s.attributes.empty());
  EXPECT_EQ(s.subvolumes[0].name, "");
  EXPECT_TRUE(s.subvolumes[0].domain.empty());
  EXPECT_EQ(s.subvolumes[0].limits[0], (Limit{"clw", std::nullopt, 0.0}));
}

TEST(SceneParseTest, CanonicalFormRoundTripsAndIsStable) {
  const Scene s = parse_scene(kSpecExample, "scene.json");
  const std::string canonical = scene_to_json(s);
  EXPECT_EQ(parse_scene(canonical, "canonical"), s);
  EXPECT_EQ(scene_to_json(parse_scene(canonical, "canonical")), canonical);
  EXPECT_EQ(
      canonical,
      R"({"format_version":1,"time":0,"subvolumes":[)"
      R"({"id":1,"name":"cloud ice","limits":[{"var":"cli","min":1e-06}],)"
      R"("domain":{"height":[0.0,12000.0],"lat":[47.0,55.0],"lon":[5.0,15.0]}},)"
      R"({"id":2,"name":"rain in warm air","limits":[{"var":"qr","min":1e-05},)"
      R"({"var":"ta","min":273.15,"max":320.0}]},)"
      R"({"id":3,"name":"column above the radar","limits":[],)"
      R"("domain":{"lat":[50.0,50.3],"lon":[7.0,7.5]}}],"attributes":["ta","ua"]})");
}

TEST(SceneParseTest, RoundTripKeepsNumbersAndNamesExactly) {
  Scene s;
  s.time = 4294967295u;
  SubVolume sv;
  sv.id = 65535;
  sv.name = "Wolke \xC3\xBC\xE2\x82\xAC \"quoted\" \\ \n\t\x01" + std::string(200, 'x');
  for (double v : {0.1, 1e-30, 1e30, 5e-324, 1.7976931348623157e308, -0.0, 273.15, 1.0 / 3.0}) {
    sv.limits.push_back(Limit{"v", v, std::nullopt});
  }
  sv.limits.push_back(Limit{"w", std::nullopt, -2.5e-310});
  sv.domain["lat"] = AxisRange{-90, 90};
  sv.domain["z"] = AxisRange{0.30000000000000004, 0.30000000000000004};
  s.subvolumes.push_back(sv);
  s.attributes = {"ua", "va", "wa"};
  const std::string json = scene_to_json(s);
  const Scene back = parse_scene(json, "json");
  EXPECT_EQ(back, s);
  for (std::size_t i = 0; i < s.subvolumes[0].limits.size(); ++i) {
    const auto& a = s.subvolumes[0].limits[i];
    const auto& b = back.subvolumes[0].limits[i];
    if (a.min) {
      EXPECT_EQ(std::signbit(*a.min), std::signbit(*b.min));
    }
  }
  EXPECT_EQ(scene_to_json(back), json);
}

TEST(SceneParseTest, WhitespaceAndKeyOrderDoNotMatter) {
  const Scene a = parse_scene(R"({"attributes":["ta"],"subvolumes":[{"limits":[{"max":2,"var":"x","min":1}],"id":3}],"time":1})", "a");
  const Scene b = parse_scene("\n\t{ \"time\" : 1 , \"subvolumes\" : [ { \"id\" : 3 , \"limits\" : [ { \"var\" : \"x\" , \"min\" : 1 , \"max\" : 2 } ] } ] , \"attributes\" : [ \"ta\" ] }\r\n", "b");
  EXPECT_EQ(a, b);
}

TEST(SceneParseTest, LeadingByteOrderMarkIsIgnored) {
  const std::string json = "\xEF\xBB\xBF" + with_limit(R"({"var": "clw", "min": 0})");
  EXPECT_EQ(parse_scene(json, "bom").subvolumes.size(), 1u);
}

TEST(SceneParseTest, InvalidJson) {
  expect_invalid(R"({"subvolumes": [)", {"not valid JSON", "line 1"});
  expect_invalid("", {"not valid JSON"});
  expect_invalid(R"({"subvolumes": [], })", {"not valid JSON"});         // trailing comma
  expect_invalid("{\"subvolumes\": [] /* c */}", {"not valid JSON"});    // comment
  expect_invalid(one_subvolume("\"name\": \"\xC3\x28\""), {"not valid JSON"});  // bad UTF-8
  expect_invalid(with_limit(R"({"var": "x", "min": NaN})"), {"not valid JSON"});
}

TEST(SceneParseTest, TopLevelNotAnObject) {
  expect_invalid(R"([{"id": 1}])", {"expected a JSON object at the top level, got an array"});
  expect_invalid("42", {"expected a JSON object"});
}

TEST(SceneParseTest, TooLarge) {
  std::string json = with_limit(R"({"var": "clw", "min": 0})");
  json.insert(1, kMaxSceneBytes, ' ');
  expect_invalid(json, {"more than the limit of 1048576"});
}

TEST(SceneParseTest, NestingTooDeep) {
  const std::string deep = std::string(40, '[') + std::string(40, ']');
  expect_invalid(fmt::format(R"({{"subvolumes": [{{"id": 1, "name": {}}}]}})", deep),
                 {"subvolumes[0].name[0][0]", "deeper than 32 levels"});
  const std::string very_deep = std::string(500000, '[') + std::string(500000, ']');
  expect_invalid(very_deep, {"deeper than 32"});
}

TEST(SceneParseTest, DuplicateKeys) {
  expect_invalid(R"({"time": 0, "time": 1, "subvolumes": []})", {"key 'time' appears twice"});
  expect_invalid(R"({"subvolumes": [{"id": 1, "limits": [{"var": "a", "min": 1}]},
                                    {"id": 2, "limits": [{"var": "a", "min": 1, "min": 2}]}]})",
                 {"subvolumes[1].limits[0]: key 'min' appears twice"});
  expect_invalid(one_subvolume(R"("domain": {"lat": [1, 2], "lat": [3, 4]})"),
                 {"subvolumes[0].domain: key 'lat' appears twice"});
}

TEST(SceneParseTest, FormatVersionNewerThanReader) {
  expect_error([] { parse_scene(R"({"format_version": 5, "slices": [], "subvolumes": []})", "s.json"); },
               ErrorCode::kVersionTooNew,
               {"s.json", "format_version 5 is newer than this reader (max 4)"});
}

TEST(SceneParseTest, FormatVersionInvalid) {
  const auto body = with_limit(R"({"var": "x", "min": 0})").substr(1);
  expect_invalid(fmt::format(R"({{"format_version": 0, {})", body),
                 {"format_version: must be an integer >= 1, got 0"});
  expect_invalid(fmt::format(R"({{"format_version": 1.0, {})", body),
                 {"format_version: expected an integer, got number 1.0"});
  expect_invalid(fmt::format(R"({{"format_version": "1", {})", body),
                 {"format_version: expected an integer, got string \"1\""});
  EXPECT_NO_THROW(parse_scene(fmt::format(R"({{"format_version": 1, {})", body), "v1"));
}

TEST(SceneParseTest, UnknownKeys) {
  expect_invalid(R"({"subvolume": [], "subvolumes": [{"id": 1, "limits": [{"var": "x", "min": 0}]}]})",
                 {"subvolume: unknown key 'subvolume'",
                  "allowed at the top level: format_version, time, subvolumes, attributes"});
  expect_invalid(one_subvolume(R"("colour": "red", "limits": [{"var": "x", "min": 0}])"),
                 {"subvolumes[0].colour: unknown key 'colour' (allowed here: id, name, limits, domain, geographic)"});
  expect_invalid(with_limit(R"({"var": "x", "min": 0, "inclusive": true})"),
                 {"subvolumes[0].limits[0].inclusive: unknown key", "var, min, max"});
}

TEST(SceneParseTest, ReservedKeys) {
  // slices, trajectories, terrain and sun became keys in version 2 (scene_version2_keys_test).
  for (const char* key : {"advection", "camera"}) {
    expect_invalid(fmt::format(R"({{"{}": {{}}, "subvolumes": [{{"id": 1, "domain": {{"x": [0, 1]}}}}]}})", key),
                   {fmt::format("{}: key '{}' is reserved for a later version", key, key)});
  }
  expect_invalid(one_subvolume(R"("style": {}, "domain": {"x": [0, 1]})"),
                 {"subvolumes[0].style: key 'style' is reserved"});
}

TEST(SceneParseTest, MissingRequiredKeys) {
  expect_invalid(R"({"time": 0})", {"missing required key 'subvolumes'"});
  expect_invalid(R"({"subvolumes": [{"name": "a", "limits": [{"var": "x", "min": 0}]}]})",
                 {"subvolumes[0]: missing required key 'id'"});
  expect_invalid(with_limit(R"({"min": 0})"), {"subvolumes[0].limits[0]: missing required key 'var'"});
}

TEST(SceneParseTest, EmptyScene) {
  expect_invalid(R"({"subvolumes": []})", {"subvolumes: a scene needs at least one sub-volume"});
}

TEST(SceneParseTest, TooManySubVolumesLimitsAndAttributes) {
  std::string svs;
  for (int i = 1; i <= 65; ++i) {
    svs += fmt::format(R"({}{{"id": {}, "domain": {{"x": [0, 1]}}}})", i > 1 ? "," : "", i);
  }
  expect_invalid(fmt::format(R"({{"subvolumes": [{}]}})", svs),
                 {"subvolumes: has 65 sub-volumes, more than the limit of 64"});
  std::string limits;
  for (int i = 0; i < 17; ++i) limits += fmt::format(R"({}{{"var": "v{}", "min": 0}})", i ? "," : "", i);
  expect_invalid(with_limit(limits), {"subvolumes[0].limits: has 17 limits, more than the limit of 16"});
  std::string attributes;
  for (int i = 0; i < 65; ++i) attributes += fmt::format(R"({}"a{}")", i ? "," : "", i);
  expect_invalid(fmt::format(R"({{"subvolumes": [{{"id": 1, "domain": {{"x": [0, 1]}}}}], "attributes": [{}]}})",
                             attributes),
                 {"attributes: has 65 names, more than the limit of 64"});
}

TEST(SceneParseTest, LimitCountsAtTheMaximumAreAccepted) {
  std::string svs;
  for (int i = 1; i <= 64; ++i) {
    svs += fmt::format(R"({}{{"id": {}, "domain": {{"x": [0, 1]}}}})", i > 1 ? "," : "", 65536 - i);
  }
  EXPECT_EQ(parse_scene(fmt::format(R"({{"subvolumes": [{}]}})", svs), "s").subvolumes.size(), 64u);
  std::string limits;
  for (int i = 0; i < 16; ++i) limits += fmt::format(R"({}{{"var": "v{}", "min": 0}})", i ? "," : "", i);
  EXPECT_EQ(parse_scene(with_limit(limits), "s").subvolumes[0].limits.size(), 16u);
}

TEST(SceneParseTest, IdOutOfRangeOrNotAnInteger) {
  const auto scene_with_id = [](std::string_view id) {
    return fmt::format(R"({{"subvolumes": [{{"id": {}, "domain": {{"x": [0, 1]}}}}]}})", id);
  };
  expect_invalid(scene_with_id("0"), {"subvolumes[0].id: must be an integer in 1..65535, got 0"});
  expect_invalid(scene_with_id("65536"), {"subvolumes[0].id: must be an integer in 1..65535, got 65536"});
  expect_invalid(scene_with_id("-1"), {"subvolumes[0].id: must be an integer in 1..65535, got -1"});
  expect_invalid(scene_with_id("18446744073709551616"), {"subvolumes[0].id: expected an integer"});
  expect_invalid(scene_with_id("1.0"), {"subvolumes[0].id: expected an integer, got number 1.0"});
  expect_invalid(scene_with_id("1e2"), {"subvolumes[0].id: expected an integer"});
  expect_invalid(scene_with_id("\"1\""), {"subvolumes[0].id: expected an integer, got string \"1\""});
  expect_invalid(scene_with_id("null"), {"subvolumes[0].id: expected an integer, got null"});
}

TEST(SceneParseTest, DuplicateIds) {
  expect_invalid(R"({"subvolumes": [{"id": 5, "domain": {"x": [0, 1]}}, {"id": 6, "domain": {"x": [0, 1]}},
                                    {"id": 5, "limits": [{"var": "a", "min": 0}]}]})",
                 {"subvolumes[2].id: id 5 is already used by subvolumes[0]"});
}

TEST(SceneParseTest, Names) {
  const std::string ok = std::string(kMaxSubVolumeNameBytes, 'n');
  EXPECT_EQ(parse_scene(one_subvolume(fmt::format(R"("name": "{}", "domain": {{"x": [0, 1]}})", ok)), "s")
                .subvolumes[0].name, ok);
  expect_invalid(one_subvolume(fmt::format(R"("name": "{}n", "domain": {{"x": [0, 1]}})", ok)),
                 {"subvolumes[0].name: has 257 bytes, more than the limit of 256"});
  expect_invalid(one_subvolume(R"("name": 3, "domain": {"x": [0, 1]})"),
                 {"subvolumes[0].name: expected a string, got integer 3"});
}

TEST(SceneParseTest, LimitWithoutBounds) {
  expect_invalid(with_limit(R"({"var": "clw"})"),
                 {"subvolumes[0].limits[0]: a limit needs 'min', 'max' or both"});
}

TEST(SceneParseTest, MinGreaterThanMax) {
  expect_invalid(R"({"subvolumes": [{"id": 1, "limits": [{"var": "a", "min": 0}]},
                                    {"id": 2, "limits": [{"var": "a", "min": 0}, {"var": "ta", "min": 300, "max": 273.15}]}]})",
                 {"subvolumes[1].limits[1]: min 300 is greater than max 273.15"});
}

TEST(SceneParseTest, MinEqualToMaxIsAccepted) {
  const Scene s = parse_scene(with_limit(R"({"var": "qr", "min": 0, "max": 0})"), "s");
  EXPECT_EQ(s.subvolumes[0].limits[0], (Limit{"qr", 0.0, 0.0}));
}

TEST(SceneParseTest, NonNumericLimitsAreWrongTypes) {
  for (const char* bad : {"\"nan\"", "\"NaN\"", "\"inf\"", "\"-Infinity\"", "\"1e-5\""}) {
    expect_invalid(with_limit(fmt::format(R"({{"var": "clw", "min": {}}})", bad)),
                   {"subvolumes[0].limits[0].min: expected a number, got string"});
    expect_invalid(with_limit(fmt::format(R"({{"var": "clw", "max": {}}})", bad)),
                   {"subvolumes[0].limits[0].max: expected a number, got string"});
  }
  expect_invalid(with_limit(R"({"var": "clw", "min": null})"),
                 {"subvolumes[0].limits[0].min: expected a number, got null"});
  expect_invalid(with_limit(R"({"var": "clw", "max": true})"),
                 {"subvolumes[0].limits[0].max: expected a number, got true"});
  expect_invalid(with_limit(R"({"var": "clw", "max": [1]})"),
                 {"subvolumes[0].limits[0].max: expected a number, got an array of 1 values"});
}

TEST(SceneParseTest, OverflowingNumbersAreNotFinite) {
  expect_invalid(with_limit(R"({"var": "clw", "min": 1e999})"),
                 {"subvolumes[0].limits[0].min: is not a finite number", "1e999"});
  expect_invalid(one_subvolume(R"("domain": {"height": [0, -1e400]})"),
                 {"subvolumes[0].domain.height[1]: is not a finite number"});
}

TEST(SceneParseTest, VariableNameWrongOrEmpty) {
  expect_invalid(with_limit(R"({"var": "", "min": 0})"),
                 {"subvolumes[0].limits[0].var: must name a variable"});
  expect_invalid(with_limit(R"({"var": 7, "min": 0})"),
                 {"subvolumes[0].limits[0].var: expected a string, got integer 7"});
}

TEST(SceneParseTest, DomainRangeShape) {
  expect_invalid(one_subvolume(R"("domain": {"lat": [1]})"),
                 {"subvolumes[0].domain.lat: expected an array of two numbers [lo, hi], got an array of 1 values"});
  expect_invalid(one_subvolume(R"("domain": {"lat": [1, 2, 3]})"),
                 {"subvolumes[0].domain.lat: expected an array of two numbers"});
  expect_invalid(one_subvolume(R"("domain": {"lat": {"lo": 1, "hi": 2}})"),
                 {"subvolumes[0].domain.lat: expected an array of two numbers [lo, hi], got an object"});
  expect_invalid(one_subvolume(R"("domain": {"lat": [1, "2"]})"),
                 {"subvolumes[0].domain.lat[1]: expected a number, got string \"2\""});
  expect_invalid(one_subvolume(R"("domain": {"lat": [null, 2]})"),
                 {"subvolumes[0].domain.lat[0]: expected a number, got null"});
  expect_invalid(one_subvolume(R"("domain": [[0, 1]])"),
                 {"subvolumes[0].domain: expected an object, got an array"});
}

TEST(SceneParseTest, DomainLoGreaterThanHi) {
  expect_invalid(one_subvolume(R"("domain": {"lat": [55.0, 47.0]})"),
                 {"subvolumes[0].domain.lat: lo 55 is greater than hi 47"});
}

TEST(SceneParseTest, DomainLoEqualToHiIsAccepted) {
  EXPECT_EQ(parse_scene(one_subvolume(R"("domain": {"height": [100, 100]})"), "s")
                .subvolumes[0].domain.at("height"), (AxisRange{100, 100}));
}

TEST(SceneParseTest, DomainWithoutLimitsIsABoxOnlySubVolume) {
  const Scene s = parse_scene(one_subvolume(R"("name": "box", "domain": {"lon": [7, 8]})"), "s");
  EXPECT_TRUE(s.subvolumes[0].limits.empty());
  EXPECT_EQ(s.subvolumes[0].domain.size(), 1u);
}

TEST(SceneParseTest, SubVolumeRestrictingNothing) {
  expect_invalid(one_subvolume(R"("name": "all")"),
                 {"subvolumes[0]: a sub-volume needs at least one limit, a domain axis or a geographic box"});
  expect_invalid(one_subvolume(R"("limits": [], "domain": {})"),
                 {"subvolumes[0]: a sub-volume needs at least one limit, a domain axis or a geographic box"});
}

TEST(SceneParseTest, Attributes) {
  const std::string sv = R"({"id": 1, "domain": {"x": [0, 1]}})";
  expect_invalid(fmt::format(R"({{"subvolumes": [{}], "attributes": ["ta", "ua", "ta"]}})", sv),
                 {"attributes[2]: 'ta' is already listed as attributes[0]"});
  expect_invalid(fmt::format(R"({{"subvolumes": [{}], "attributes": ["ta", 1]}})", sv),
                 {"attributes[1]: expected a string, got integer 1"});
  expect_invalid(fmt::format(R"({{"subvolumes": [{}], "attributes": "ta"}})", sv),
                 {"attributes: expected an array, got string \"ta\""});
  expect_invalid(fmt::format(R"({{"subvolumes": [{}], "attributes": [""]}})", sv),
                 {"attributes[0]: must name a variable"});
}

TEST(SceneParseTest, TimeOutOfRangeOrWrongType) {
  const std::string sv = R"("subvolumes": [{"id": 1, "domain": {"x": [0, 1]}}])";
  expect_invalid(fmt::format(R"({{"time": -1, {}}})", sv), {"time: must be an integer in 0..4294967295, got -1"});
  expect_invalid(fmt::format(R"({{"time": 4294967296, {}}})", sv), {"time: must be an integer in 0..4294967295"});
  expect_invalid(fmt::format(R"({{"time": 0.5, {}}})", sv), {"time: expected an integer, got number 0.5"});
  expect_invalid(fmt::format(R"({{"time": "0", {}}})", sv), {"time: expected an integer, got string"});
  EXPECT_EQ(parse_scene(fmt::format(R"({{"time": 4294967295, {}}})", sv), "s").time, 4294967295u);
}

TEST(SceneParseTest, ContainersOfTheWrongType) {
  expect_invalid(R"({"subvolumes": {"id": 1}})", {"subvolumes: expected an array, got an object"});
  expect_invalid(R"({"subvolumes": ["cloud"]})", {"subvolumes[0]: expected an object, got string \"cloud\""});
  expect_invalid(one_subvolume(R"("limits": {"var": "x", "min": 0})"),
                 {"subvolumes[0].limits: expected an array, got an object"});
  expect_invalid(one_subvolume(R"("limits": [["x", 0]])"),
                 {"subvolumes[0].limits[0]: expected an object, got an array of 2 values"});
}

TEST(SceneParseTest, LongStringsAreShortenedInMessages) {
  const std::string message = expect_error(
      [] { parse_scene(with_limit(fmt::format(R"({{"var": "x", "min": "{}"}})", std::string(5000, 'z'))), "s"); },
      ErrorCode::kInvalidInput, {"expected a number, got string \"zzz", "...\""});
  EXPECT_LT(message.size(), 200u);
}

TEST(SceneParseTest, HostileKeysAreShortenedAndEscapedInMessages) {
  const std::string key = "\\u001b[2J" + std::string(1000, 'k');
  const std::string message = expect_error(
      [&] { parse_scene(fmt::format(R"({{"{}": 1, "subvolumes": []}})", key), "s"); },
      ErrorCode::kInvalidInput, {"unknown key '\\x1b[2Jkkk", "kkk...' (allowed at the top level"});
  EXPECT_LT(message.size(), 300u);
  EXPECT_EQ(message.find('\x1b'), std::string::npos);
  expect_error([] { parse_scene(one_subvolume(R"("domain": {"\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc\u00fc": [2, 1]})"), "s"); },
               ErrorCode::kInvalidInput,
               {"subvolumes[0].domain.\xC3\xBC\xC3\xBC", "\xC3\xBC...: lo 2 is greater than hi 1"});
}

TEST(SceneParseTest, ValidateRejectsScenesBuiltInCode) {
  Scene s;
  s.subvolumes.push_back(SubVolume{1, "a", {Limit{"clw", std::nan(""), std::nullopt}}, {}});
  expect_error([&] { validate_scene(s, "panel"); }, ErrorCode::kInvalidInput,
               {"panel: subvolumes[0].limits[0].min: must be a finite number, got nan"});
  s.subvolumes[0].limits[0].min = std::numeric_limits<double>::infinity();
  expect_error([&] { scene_to_json(s); }, ErrorCode::kInvalidInput,
               {"scene: subvolumes[0].limits[0].min: must be a finite number, got inf"});
  s.subvolumes[0].limits[0].min = 1;
  s.subvolumes[0].domain["lat"] = AxisRange{0, std::nan("")};
  expect_error([&] { validate_scene(s, "panel"); }, ErrorCode::kInvalidInput,
               {"subvolumes[0].domain.lat[1]: must be a finite number"});
  s.subvolumes[0].domain.clear();
  s.subvolumes[0].name = "\xFF";
  expect_error([&] { scene_to_json(s); }, ErrorCode::kInvalidInput,
               {"subvolumes[0].name: is not valid UTF-8"});
  s.subvolumes[0].name = "ok";
  s.subvolumes[0].id = 0;
  expect_error([&] { validate_scene(s, "panel"); }, ErrorCode::kInvalidInput,
               {"subvolumes[0].id: must be an integer in 1..65535, got 0"});
  s.subvolumes[0].id = 70000;
  expect_error([&] { validate_scene(s, "panel"); }, ErrorCode::kInvalidInput,
               {"subvolumes[0].id: must be an integer in 1..65535, got 70000"});
}

TEST(SceneParseTest, LoadSceneFile) {
  const testing::TempDir dir;
  const auto good = dir.path() / "good.json";
  std::ofstream(good) << kSpecExample;
  EXPECT_EQ(load_scene_file(good), parse_scene(kSpecExample, "x"));

  const auto bad = dir.path() / "bad.json";
  std::ofstream(bad) << with_limit(R"({"var": "clw", "min": "nan"})");
  expect_error([&] { load_scene_file(bad); }, ErrorCode::kInvalidInput,
               {bad.string(), "subvolumes[0].limits[0].min: expected a number"});

  expect_error([&] { load_scene_file(dir.path() / "missing.json"); }, ErrorCode::kNotFound,
               {(dir.path() / "missing.json").string()});
  expect_error([&] { load_scene_file(dir.path()); }, ErrorCode::kIo, {dir.path().string()});

  const auto big = dir.path() / "big.json";
  std::ofstream(big) << std::string(kMaxSceneBytes + 1, ' ');
  expect_error([&] { load_scene_file(big); }, ErrorCode::kInvalidInput,
               {big.string(), "1048577 bytes, more than the limit of 1048576"});
}

}  // namespace
}  // namespace strielad
