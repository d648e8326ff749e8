// SPDX-License-Identifier: Apache-2.0
// Stores without a grid geometry are written byte for byte as before the geometry record
// existed: same format version, same plan (store_id) and same manifest bytes. The
// expected checksums were taken from the writer before format version 5.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "core/checksum.h"
#include "format/manifest.h"

namespace strielad::format {
namespace {

Manifest plan(AxisKind x_kind, AxisKind y_kind) {
  Manifest m;
  m.tool_version = "test";
  m.x = Axis{"x", x_kind, "degrees", "", "", "", {0, 120, 240}};
  m.y = Axis{"y", y_kind, "degrees", "", "", "", {-10, 10}};
  m.z = Axis{"lev", AxisKind::kPressure, "hPa", "", "", "down", {1000, 850, 500}};
  m.time = TimeAxis{"time", "hours since 2000-01-01", "standard", {0, 6}};
  StoreVariable v;
  v.name = "t";
  v.units = "K";
  v.fill_value = -999.0;
  m.variables.push_back(v);
  m.brick = 4;
  m.sources.push_back(SourceRecord{"/data/t.nc", 4096, 0xabcdefull});
  return m;
}

Manifest sealed(Manifest m) {
  m.format_version = version_for_plan(m);
  m.store_id = compute_store_id(m);
  return m;
}

std::uint64_t manifest_bytes_checksum(const Manifest& m) {
  return checksum64(encode_manifest(m));
}

TEST(ManifestPlanStabilityTest, PlansWithoutGeometryKeepTheirVersionIdAndBytes) {
  const Manifest lonlat = sealed(plan(AxisKind::kLongitude, AxisKind::kLatitude));
  Manifest fpzip_plan = plan(AxisKind::kLongitude, AxisKind::kLatitude);
  fpzip_plan.codec.fpzip = true;
  const Manifest fpzip = sealed(fpzip_plan);
  Manifest rotated_plan = plan(AxisKind::kProjectionX, AxisKind::kProjectionY);
  GridMapping g;
  g.variable = "rotated_pole";
  g.name = "rotated_latitude_longitude";
  g.attributes = {{"grid_north_pole_latitude", 39.25}, {"grid_north_pole_longitude", -162.0}};
  g.proj = "+proj=ob_tran +o_proj=longlat";
  rotated_plan.grid_mapping = g;
  const Manifest rotated = sealed(rotated_plan);

  EXPECT_EQ(lonlat.format_version, 2u);
  EXPECT_EQ(fpzip.format_version, 3u);
  EXPECT_EQ(rotated.format_version, 4u);
  EXPECT_FALSE(manifest_plan_json(rotated).contains("geometry"));
  EXPECT_EQ(fmt::format("{:016x}", lonlat.store_id), "cf42999419f68ed8");
  EXPECT_EQ(fmt::format("{:016x}", fpzip.store_id), "c78a42991950b0b0");
  EXPECT_EQ(fmt::format("{:016x}", rotated.store_id), "5a9f089d5cf8a1ec");
  EXPECT_EQ(fmt::format("{:016x}", manifest_bytes_checksum(lonlat)), "d5d8007959d74b7c");
  EXPECT_EQ(fmt::format("{:016x}", manifest_bytes_checksum(fpzip)), "b19257fe2e50d7f0");
  EXPECT_EQ(fmt::format("{:016x}", manifest_bytes_checksum(rotated)), "8dde7e79058aabb4");
}

}  // namespace
}  // namespace strielad::format
