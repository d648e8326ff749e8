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
               {"version 9 is newer than this reader (max 1)"});
}

// Re-frames a JSON payload with a valid checksum, so that only the content rules apply.
std::vector<std::byte> frame(const std::string& payload) {
  auto bytes = encode_manifest(sample_manifest());
  std::vector<std::byte> out(bytes.begin(), bytes.begin() + 16);
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

}  // namespace
}  // namespace strielad::format
