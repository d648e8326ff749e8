// SPDX-License-Identifier: Apache-2.0
#include "format/manifest.h"

#include <gtest/gtest.h>

#include <cstring>

#include "core/checksum.h"
#include "support/expect_error.h"

namespace strielad::format {
namespace {

using testing::expect_error;

Manifest sample_manifest() {
  Manifest m;
  m.tool_version = "test";
  m.x = Axis{"lon", AxisKind::kLongitude, "degrees_east", "longitude", "", "", {4.5, 4.6, 4.8}};
  m.y = Axis{"lat", AxisKind::kLatitude, "degrees_north", "latitude", "", "", {54.5, 54.0}};
  m.z = Axis{"height", AxisKind::kHeight, "m", "height", "", "up", {21000.0, 1234.5678901234567, 20.0}};
  m.time = TimeAxis{"time", "seconds since 2013-04-26 00:00:00", "proleptic_gregorian", {0, 300}};
  m.variables.push_back(StoreVariable{"clw", "kg kg-1", "cloud water", "", DType::kFloat32, "float",
                                      -9e33, std::nullopt, std::nullopt, std::nullopt,
                                      std::nullopt, std::nullopt});
  m.brick = 16;
  m.sources.push_back(SourceRecord{"/data/a.nc", 1234, 0xfeedull});
  m.store_id = compute_store_id(m);
  return m;
}

TEST(ManifestTest, RoundTripKeepsAxisValuesExactly) {
  const Manifest m = sample_manifest();
  const Manifest back = decode_manifest(encode_manifest(m), "MANIFEST");
  EXPECT_EQ(back.z.values, m.z.values);
  EXPECT_EQ(back.store_id, m.store_id);
  EXPECT_EQ(back.variables, m.variables);
  EXPECT_EQ(back.sources, m.sources);
  EXPECT_FALSE(back.complete);
}

TEST(ManifestTest, CompleteManifestRoundTripsStepsAndSummary) {
  Manifest m = sample_manifest();
  m.complete = true;
  m.steps = {StepRecord{0, step_file_name(0), 100, 1}, StepRecord{1, step_file_name(1), 200, 2}};
  m.summary = nlohmann::json{{"ratio", 3.5}};
  const Manifest back = decode_manifest(encode_manifest(m), "MANIFEST");
  EXPECT_TRUE(back.complete);
  EXPECT_EQ(back.steps, m.steps);
  EXPECT_EQ(back.summary, m.summary);
  EXPECT_EQ(step_file_name(42), "steps/step-000042.bricks");
}

TEST(ManifestTest, StoreIdDependsOnThePlanOnly) {
  Manifest a = sample_manifest(), b = sample_manifest();
  b.tool_version = "other";
  b.complete = true;
  EXPECT_EQ(compute_store_id(a), compute_store_id(b));
  b.brick = 20;
  EXPECT_NE(compute_store_id(a), compute_store_id(b));
}

TEST(ManifestTest, CorruptMagic) {
  auto bytes = encode_manifest(sample_manifest());
  bytes[3] = std::byte{'?'};
  expect_error([&] { decode_manifest(bytes, "S/MANIFEST"); }, ErrorCode::kCorrupt,
               {"S/MANIFEST", "bad magic"});
}

TEST(ManifestTest, CorruptChecksum) {
  auto bytes = encode_manifest(sample_manifest());
  bytes[100] ^= std::byte{0x20};
  expect_error([&] { decode_manifest(bytes, "S/MANIFEST"); }, ErrorCode::kCorrupt,
               {"checksum mismatch"});
}

TEST(ManifestTest, Truncated) {
  const auto bytes = encode_manifest(sample_manifest());
  expect_error([&] { decode_manifest(std::span(bytes).first(bytes.size() - 5), "S/MANIFEST"); },
               ErrorCode::kTruncated, {"S/MANIFEST"});
  expect_error([&] { decode_manifest(std::span(bytes).first(10), "S/MANIFEST"); },
               ErrorCode::kTruncated, {"S/MANIFEST"});
}

TEST(ManifestTest, InvalidVersion) {
  auto bytes = encode_manifest(sample_manifest());
  bytes[8] = std::byte{9};
  expect_error([&] { decode_manifest(bytes, "S/MANIFEST"); }, ErrorCode::kVersionTooNew,
               {fmt::format("version 9 is newer than this reader (max {})", format::kManifestFormatVersion)});
  bytes[8] = std::byte{0};
  expect_error([&] { decode_manifest(bytes, "S/MANIFEST"); }, ErrorCode::kCorrupt,
               {"version 0"});
}

// Re-frames a JSON payload with a valid checksum, so that only the content rules apply.
std::vector<std::byte> frame(const std::string& payload, std::uint32_t version = 2) {
  auto bytes = encode_manifest(sample_manifest());
  std::vector<std::byte> out(bytes.begin(), bytes.begin() + 16);
  std::memcpy(out.data() + 8, &version, 4);
  const std::uint64_t n = payload.size();
  out.resize(24);
  std::memcpy(out.data() + 16, &n, 8);
  for (char c : payload) out.push_back(static_cast<std::byte>(c));
  const std::uint64_t sum = checksum64(out);
  out.resize(out.size() + 8);
  std::memcpy(out.data() + out.size() - 8, &sum, 8);
  return out;
}

TEST(ManifestTest, ContentRulesAreEnforced) {
  auto j = manifest_to_json(sample_manifest());
  j.erase("codec");
  expect_error([&] { decode_manifest(frame(j.dump()), "M"); }, ErrorCode::kCorrupt,
               {"missing key 'codec'"});
  j = manifest_to_json(sample_manifest());
  j["grid"]["z"]["values"] = {1.0, 3.0, 2.0};
  expect_error([&] { decode_manifest(frame(j.dump()), "M"); }, ErrorCode::kCorrupt,
               {"grid.z", "not strictly monotonic"});
  j = manifest_to_json(sample_manifest());
  j["octree"]["levels"][0]["nodes"] = {9, 9, 9};
  expect_error([&] { decode_manifest(frame(j.dump()), "M"); }, ErrorCode::kCorrupt,
               {"octree level table"});
  j = manifest_to_json(sample_manifest());
  j["brick"] = 17;
  j["variables"][0]["units"] = "g/kg";
  expect_error([&] { decode_manifest(frame(j.dump()), "M"); }, ErrorCode::kCorrupt,
               {"store_id"});
  expect_error([&] { decode_manifest(frame("{not json"), "M"); }, ErrorCode::kCorrupt,
               {"not valid JSON"});
}

TEST(ManifestTest, WritesVersion2WithPredictorsAndPerVariableCodecs) {
  Manifest m = sample_manifest();
  m.codec.predictor = "lorenzo3";
  m.variables.push_back(m.variables[0]);
  m.variables[1].name = "ta";
  m.variables[1].codec = CodecSpec{"lz4", 5, "bit", "none"};
  m.store_id = compute_store_id(m);
  const auto bytes = encode_manifest(m);
  std::uint32_t frame_version = 0;
  std::memcpy(&frame_version, bytes.data() + 8, 4);
  EXPECT_EQ(frame_version, 2u);
  const auto j = manifest_to_json(m);
  EXPECT_EQ(j["format_version"], 2);
  EXPECT_EQ(j["codec"]["predictor"], "lorenzo3");
  EXPECT_FALSE(j["variables"][0].contains("codec"));
  EXPECT_EQ(j["variables"][1]["codec"]["predictor"], "none");

  const Manifest back = decode_manifest(bytes, "MANIFEST");
  EXPECT_EQ(back.format_version, 2u);
  EXPECT_EQ(back.codec, m.codec);
  EXPECT_EQ(back.variables, m.variables);
  EXPECT_EQ(back.codec_of(0).predictor, "lorenzo3");
  EXPECT_EQ(back.codec_of(1), (CodecSpec{"lz4", 5, "bit", "none"}));
}

TEST(ManifestTest, StoreIdCoversPredictorsAndPerVariableCodecs) {
  const Manifest a = sample_manifest();
  Manifest b = a;
  b.codec.predictor = "lorenzo3";
  EXPECT_NE(compute_store_id(a), compute_store_id(b));
  Manifest c = a;
  c.variables[0].codec = a.codec;  // the same settings, but stated per variable
  EXPECT_NE(compute_store_id(a), compute_store_id(c));
  Manifest d = c;
  d.variables[0].codec->predictor = "lorenzo3";
  EXPECT_NE(compute_store_id(c), compute_store_id(d));
}

TEST(ManifestTest, UnknownOrMissingPredictorIsRejected) {
  auto j = manifest_to_json(sample_manifest());
  j["codec"]["predictor"] = "delta";
  expect_error([&] { decode_manifest(frame(j.dump()), "M"); }, ErrorCode::kCorrupt,
               {"M", "predictor 'delta' is not one of none, lorenzo3"});
  j = manifest_to_json(sample_manifest());
  j["codec"].erase("predictor");
  expect_error([&] { decode_manifest(frame(j.dump()), "M"); }, ErrorCode::kCorrupt,
               {"missing key 'predictor'"});
  j = manifest_to_json(sample_manifest());
  j["variables"][0]["codec"] = {{"name", "zstd"}, {"level", 1}, {"shuffle", "byte"},
                                {"predictor", "lorenzo4"}};
  expect_error([&] { decode_manifest(frame(j.dump()), "M"); }, ErrorCode::kCorrupt,
               {"variable 'clw'", "predictor 'lorenzo4'"});
  j = manifest_to_json(sample_manifest());
  j["variables"][0]["codec"] = {{"name", "zstd"}, {"level", 1}, {"shuffle", "byte"}};
  expect_error([&] { decode_manifest(frame(j.dump()), "M"); }, ErrorCode::kCorrupt,
               {"variable 'clw'", "missing key 'predictor'"});
  j = manifest_to_json(sample_manifest());
  j["variables"][0]["codec"] = "zstd";
  expect_error([&] { decode_manifest(frame(j.dump()), "M"); }, ErrorCode::kCorrupt,
               {"variable 'clw'", "not an object"});
}

Manifest sample_manifest_v1() {
  Manifest m = sample_manifest();
  m.format_version = 1;
  m.store_id = compute_store_id(m);
  return m;
}

TEST(ManifestTest, Version1ReadsAsPredictorNone) {
  const Manifest m = sample_manifest_v1();
  const auto j = manifest_to_json(m);
  EXPECT_EQ(j["format_version"], 1);
  EXPECT_FALSE(j["codec"].contains("predictor"));
  const auto bytes = encode_manifest(m);
  EXPECT_EQ(bytes[8], std::byte{1});
  const Manifest back = decode_manifest(bytes, "MANIFEST");
  EXPECT_EQ(back.format_version, 1u);
  EXPECT_EQ(back.codec.predictor, "none");
  EXPECT_EQ(back.store_id, m.store_id);
  // Re-encoding keeps version 1 and the store_id (finalize of an old store).
  EXPECT_EQ(encode_manifest(back), bytes);
}

TEST(ManifestTest, Version1CannotHoldVersion2Features) {
  auto j = manifest_to_json(sample_manifest_v1());
  j["codec"]["predictor"] = "none";
  expect_error([&] { decode_manifest(frame(j.dump(), 1), "M"); }, ErrorCode::kCorrupt,
               {"'predictor' needs format version 2"});
  j = manifest_to_json(sample_manifest_v1());
  j["variables"][0]["codec"] = manifest_to_json(sample_manifest())["codec"];
  expect_error([&] { decode_manifest(frame(j.dump(), 1), "M"); }, ErrorCode::kCorrupt,
               {"variable 'clw'", "'codec' needs format version 2"});
  Manifest m = sample_manifest_v1();
  m.codec.predictor = "lorenzo3";
  expect_error([&] { encode_manifest(m); }, ErrorCode::kInvalidArgument, {"version 1"});
}

TEST(ManifestTest, FrameAndPayloadVersionsMustAgree) {
  const auto j = manifest_to_json(sample_manifest_v1());
  expect_error([&] { decode_manifest(frame(j.dump(), 2), "M"); }, ErrorCode::kCorrupt,
               {"frame says format version 2 but the payload says 1"});
}

Manifest sample_manifest_fpzip() {
  Manifest m = sample_manifest();
  m.variables.push_back(m.variables[0]);
  m.variables[1].name = "ta";
  m.variables[0].codec = m.codec;
  m.variables[0].codec->fpzip = true;
  m.format_version = version_for_codecs(m);
  m.store_id = compute_store_id(m);
  return m;
}

TEST(ManifestTest, AnFpzipCodecMakesVersion3AndRoundTrips) {
  EXPECT_EQ(version_for_codecs(sample_manifest()), 2u);
  const Manifest m = sample_manifest_fpzip();
  EXPECT_EQ(m.format_version, 3u);
  const auto j = manifest_to_json(m);
  EXPECT_EQ(j["variables"][0]["codec"]["fpzip"], true);
  EXPECT_FALSE(j["codec"].contains("fpzip"));  // left out when false
  const auto bytes = encode_manifest(m);
  EXPECT_EQ(bytes[8], std::byte{3});
  const Manifest back = decode_manifest(bytes, "MANIFEST");
  EXPECT_EQ(back.format_version, 3u);
  EXPECT_TRUE(back.codec_of(0).fpzip);
  EXPECT_FALSE(back.codec_of(1).fpzip);
  EXPECT_EQ(back.variables, m.variables);
  EXPECT_EQ(encode_manifest(back), bytes);
  // fpzip is part of the plan.
  Manifest other = m;
  other.variables[0].codec->fpzip = false;
  other.format_version = version_for_codecs(other);
  EXPECT_NE(compute_store_id(other), m.store_id);
}

TEST(ManifestTest, FpzipNeedsVersion3AndVersion3NeedsFpzip) {
  auto j = manifest_to_json(sample_manifest_fpzip());
  expect_error([&] { decode_manifest(frame(j.dump(), 2), "M"); }, ErrorCode::kCorrupt,
               {"frame says format version 2 but the payload says 3"});
  j["format_version"] = 2;
  expect_error([&] { decode_manifest(frame(j.dump(), 2), "M"); }, ErrorCode::kCorrupt,
               {"variable 'clw'", "'fpzip' needs format version 3"});
  j = manifest_to_json(sample_manifest_fpzip());
  j["variables"][0]["codec"]["fpzip"] = "yes";
  expect_error([&] { decode_manifest(frame(j.dump(), 3), "M"); }, ErrorCode::kCorrupt,
               {"variable 'clw'", "'fpzip' is not a bool"});
  j = manifest_to_json(sample_manifest_fpzip());
  j["variables"][0]["codec"]["fpzip"] = false;
  expect_error([&] { decode_manifest(frame(j.dump(), 3), "M"); }, ErrorCode::kCorrupt,
               {"M", "format version 3 but no codec has 'fpzip'"});
  // A writer cannot mix them up either.
  Manifest m = sample_manifest_fpzip();
  m.format_version = 2;
  expect_error([&] { encode_manifest(m); }, ErrorCode::kInvalidArgument, {"version 2", "fpzip"});
  m = sample_manifest();
  m.format_version = 3;
  expect_error([&] { encode_manifest(m); }, ErrorCode::kInvalidArgument, {"version 3", "fpzip"});
}

}  // namespace
}  // namespace strielad::format
