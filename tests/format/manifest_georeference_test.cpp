// SPDX-License-Identifier: Apache-2.0
// Manifest version 4: the grid mapping, projection axis kinds and periodic longitude axes
// round-trip; a store without them stays at its older version, byte for byte; readers
// reject version-4 keys in older versions, a version 4 without them, and a periodic axis
// that is not a longitude turned once round.
#include <gtest/gtest.h>

#include "format/manifest.h"
#include "support/expect_error.h"

namespace strielad::format {
namespace {

using testing::expect_error;

Manifest base() {
  Manifest m;
  m.tool_version = "test";
  m.x = Axis{"lon", AxisKind::kLongitude, "degrees_east", "longitude", "", "", {0, 120, 240}};
  m.y = Axis{"lat", AxisKind::kLatitude, "degrees_north", "latitude", "", "", {-10, 10}};
  m.z = Axis{"lev", AxisKind::kPressure, "hPa", "", "", "", {1000, 500}};
  m.time = TimeAxis{"time", "hours since 2000-01-01", "standard", {0}};
  StoreVariable v;
  v.name = "t";
  m.variables.push_back(v);
  m.brick = 4;
  return m;
}

Manifest periodic() {
  Manifest m = base();
  m.x.values = {0, 120, 240, 360};
  m.x.periodic = true;
  m.format_version = version_for_plan(m);
  m.store_id = compute_store_id(m);
  return m;
}

Manifest rotated() {
  Manifest m = base();
  m.x = Axis{"rlon", AxisKind::kProjectionX, "degrees", "grid_longitude", "", "", {-1, 0, 1}};
  m.y = Axis{"rlat", AxisKind::kProjectionY, "degrees", "grid_latitude", "", "", {-1, 1}};
  GridMapping g;
  g.variable = "rotated_pole";
  g.name = "rotated_latitude_longitude";
  g.attributes = {{"grid_mapping_name", "rotated_latitude_longitude"},
                  {"grid_north_pole_latitude", 39.25},
                  {"grid_north_pole_longitude", -162.0}};
  g.proj = "+proj=pipeline +step +proj=unitconvert +xy_in=deg +xy_out=rad";
  m.grid_mapping = g;
  m.format_version = version_for_plan(m);
  m.store_id = compute_store_id(m);
  return m;
}

TEST(ManifestGeoreferenceTest, RoundTripsMappingKindsAndPeriodicAxes) {
  for (const Manifest& m : {periodic(), rotated()}) {
    EXPECT_EQ(m.format_version, kManifestVersionGeoreference);
    const Manifest back = decode_manifest(encode_manifest(m), "MANIFEST");
    EXPECT_EQ(back.x, m.x);
    EXPECT_EQ(back.y, m.y);
    EXPECT_EQ(back.grid_mapping, m.grid_mapping);
    EXPECT_EQ(back.store_id, m.store_id);
  }
}

TEST(ManifestGeoreferenceTest, StoresWithoutThemKeepTheirVersion) {
  Manifest m = base();
  EXPECT_EQ(version_for_plan(m), kManifestVersionPredictors);
  m.codec.fpzip = true;
  EXPECT_EQ(version_for_plan(m), kManifestVersionFpzip);
  // fpzip in a georeferenced store: version 4 holds both.
  Manifest p = periodic();
  p.codec.fpzip = true;
  p.format_version = version_for_plan(p);
  p.store_id = compute_store_id(p);
  EXPECT_EQ(p.format_version, kManifestVersionGeoreference);
  EXPECT_TRUE(decode_manifest(encode_manifest(p), "M").codec.fpzip);
}

TEST(ManifestGeoreferenceTest, WritersRefuseAVersionThatDoesNotFit) {
  Manifest m = periodic();
  m.format_version = kManifestVersionPredictors;
  expect_error([&] { encode_manifest(m); }, ErrorCode::kInvalidArgument,
               {"a version 2 manifest cannot hold a grid mapping", "version 4"});
  Manifest b = base();
  b.format_version = kManifestVersionGeoreference;
  expect_error([&] { encode_manifest(b); }, ErrorCode::kInvalidArgument, {"needs"});
}

// The manifest's JSON payload edited, then decoded.
Manifest decode_edited(const Manifest& m, const std::function<void(nlohmann::json&)>& edit) {
  nlohmann::json j = manifest_to_json(m);
  edit(j);
  return manifest_from_json(j, "MANIFEST");
}

TEST(ManifestGeoreferenceTest, ReadersRejectVersion4KeysElsewhere) {
  expect_error([] { decode_edited(periodic(), [](auto& j) { j["format_version"] = 2; }); },
               ErrorCode::kCorrupt, {"MANIFEST: grid.x", "'periodic' needs format version 4"});
  expect_error([] { decode_edited(rotated(), [](auto& j) { j["format_version"] = 3; }); },
               ErrorCode::kCorrupt, {"axis kind 'projection_x' needs format version 4"});
  expect_error([] {
    decode_edited(rotated(), [](auto& j) {
      j["grid"]["x"]["kind"] = "longitude";
      j["grid"]["y"]["kind"] = "latitude";
      j["grid"].erase("mapping");
    });
  }, ErrorCode::kCorrupt, {"format version 4 but the grid has no grid mapping"});
  expect_error([] {
    decode_edited(periodic(), [](auto& j) { j["grid"]["x"]["values"] = {0, 120, 240, 359}; });
  }, ErrorCode::kCorrupt, {"'lon' is marked periodic"});
  expect_error([] { decode_edited(periodic(), [](auto& j) { j["grid"]["y"]["periodic"] = true; }); },
               ErrorCode::kCorrupt, {"periodic"});
  expect_error([] { decode_edited(rotated(), [](auto& j) { j["grid"]["y"]["kind"] = "latitude"; }); },
               ErrorCode::kCorrupt, {"do not match the grid mapping"});
  expect_error([] { decode_edited(rotated(), [](auto& j) { j["grid"]["mapping"]["attributes"] = 3; }); },
               ErrorCode::kCorrupt, {"grid.mapping", "'attributes' is not an object"});
  expect_error([] { decode_edited(rotated(), [](auto& j) { j["grid"]["mapping"].erase("proj"); }); },
               ErrorCode::kCorrupt, {"grid.mapping", "missing key 'proj'"});
}

}  // namespace
}  // namespace strielad::format
