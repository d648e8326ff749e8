// SPDX-License-Identifier: Apache-2.0
// Manifest version 6 (formats/store.md, "zfp chunks (version 6)"): a variable codec's
// `zfp` object (mode, value, resolved tolerance) round-trips and is part of the plan; a
// plan is written as version 6 exactly when some codec is lossy, whatever else it holds;
// readers reject a `zfp` key before version 6, a version-6 manifest without one, and zfp
// objects that are malformed or combined with fpzip.
#include <gtest/gtest.h>

#include "format/manifest.h"
#include "support/expect_error.h"

namespace strielad::format {
namespace {

using nlohmann::json;
using testing::expect_error;

Manifest lossy_manifest() {
  Manifest m;
  m.tool_version = "test";
  m.x = Axis{"lon", AxisKind::kLongitude, "degrees_east", "longitude", "", "", {4.5, 4.6, 4.8}};
  m.y = Axis{"lat", AxisKind::kLatitude, "degrees_north", "latitude", "", "", {54.5, 54.0}};
  m.z = Axis{"height", AxisKind::kHeight, "m", "height", "", "up", {2000.0, 20.0}};
  m.time = TimeAxis{"time", "seconds since 2013-04-26 00:00:00", "proleptic_gregorian", {0}};
  for (const char* name : {"ta", "clw"}) {
    StoreVariable v;
    v.name = name;
    v.source_type = "float";
    m.variables.push_back(v);
  }
  CodecSpec ta = m.codec;
  ta.zfp = LossySpec{LossyMode::kAbsolute, 0.05, 0.05};
  m.variables[0].codec = ta;
  m.brick = 16;
  m.format_version = version_for_plan(m);
  m.store_id = compute_store_id(m);
  return m;
}

TEST(ManifestLossyTest, RoundTripsAsVersionSix) {
  const Manifest m = lossy_manifest();
  EXPECT_EQ(m.format_version, kManifestVersionLossy);
  EXPECT_TRUE(has_lossy_codec(m));
  const Manifest back = decode_manifest(encode_manifest(m), "MANIFEST");
  EXPECT_EQ(back.variables, m.variables);
  EXPECT_EQ(back.codec_of(0).zfp, m.variables[0].codec->zfp);
  EXPECT_FALSE(back.codec_of(1).zfp.has_value());
  const json j = manifest_to_json(m);
  EXPECT_EQ(j["variables"][0]["codec"]["zfp"],
            (json{{"mode", "abs"}, {"value", 0.05}, {"tolerance", 0.05}}));
}

TEST(ManifestLossyTest, ToleranceIsPartOfThePlan) {
  Manifest a = lossy_manifest(), b = lossy_manifest();
  b.variables[0].codec->zfp = LossySpec{LossyMode::kAbsolute, 0.1, 0.1};
  EXPECT_NE(compute_store_id(a), compute_store_id(b));
}

TEST(ManifestLossyTest, WithoutLossyCodecsVersionsStayAsBefore) {
  Manifest m = lossy_manifest();
  m.variables[0].codec.reset();
  EXPECT_EQ(version_for_plan(m), kManifestVersionPredictors);
  m.variables[0].codec = m.codec;
  m.variables[0].codec->fpzip = true;
  EXPECT_EQ(version_for_plan(m), kManifestVersionFpzip);
  m.variables[1].codec = CodecSpec{};
  m.variables[1].codec->zfp = LossySpec{LossyMode::kRelative, 1e-3, 2e-6};
  EXPECT_EQ(version_for_plan(m), kManifestVersionLossy);  // fpzip and lossy variables together
  m.format_version = kManifestVersionLossy;
  m.store_id = compute_store_id(m);
  EXPECT_EQ(decode_manifest(encode_manifest(m), "MANIFEST").variables, m.variables);
}

TEST(ManifestLossyTest, WritersRefuseAVersionThatDoesNotFit) {
  Manifest m = lossy_manifest();
  m.format_version = 5;
  expect_error([&] { manifest_plan_json(m); }, ErrorCode::kInvalidArgument, {"version 5", "zfp"});
  m = lossy_manifest();
  m.variables[0].codec.reset();
  expect_error([&] { manifest_plan_json(m); }, ErrorCode::kInvalidArgument, {"version 6", "needs"});
}

json lossy_json() { return manifest_to_json(lossy_manifest()); }

TEST(ManifestLossyTest, ReadersRejectZfpBeforeVersionSixAndVersionSixWithoutIt) {
  json j = lossy_json();
  j["format_version"] = 2;
  expect_error([&] { manifest_from_json(j, "MANIFEST"); }, ErrorCode::kCorrupt,
               {"MANIFEST", "'zfp' needs format version 6"});
  j = lossy_json();
  j["variables"][0].erase("codec");
  expect_error([&] { manifest_from_json(j, "MANIFEST"); }, ErrorCode::kCorrupt,
               {"MANIFEST", "format version 6 but no codec has 'zfp'"});
}

TEST(ManifestLossyTest, ReadersRejectMalformedZfpObjects) {
  const auto reject = [](const std::function<void(json&)>& edit, std::string_view part) {
    json j = lossy_json();
    edit(j["variables"][0]["codec"]);
    expect_error([&] { manifest_from_json(j, "MANIFEST"); }, ErrorCode::kCorrupt,
                 {"MANIFEST", "'ta'", part});
  };
  reject([](json& c) { c["zfp"] = 0.05; }, "not an object");
  reject([](json& c) { c["zfp"]["mode"] = "pw"; }, "mode 'pw'");
  reject([](json& c) { c["zfp"]["tolerance"] = -0.05; }, "tolerance");
  reject([](json& c) { c["zfp"]["value"] = 0.0; }, "tolerance");
  reject([](json& c) { c["zfp"]["tolerance"] = 0.1; }, "differs");
  reject([](json& c) { c["zfp"].erase("value"); }, "value");
  reject([](json& c) { c["zfp"]["extra"] = 1; }, "unknown key 'extra'");
  reject([](json& c) { c["fpzip"] = true; }, "both zfp and fpzip");
}

}  // namespace
}  // namespace strielad::format
