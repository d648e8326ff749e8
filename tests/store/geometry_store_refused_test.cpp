// SPDX-License-Identifier: Apache-2.0
// A store whose manifest records a grid geometry (format 5) is refused by name: this
// build's readers would place its samples on the index lattice, a wrong answer that
// looks right. Stores without one open as before.
#include <gtest/gtest.h>

#include "core/file_io.h"
#include "format/manifest.h"
#include "store/store.h"
#include "support/expect_error.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using testing::expect_error;

format::Manifest hybrid_height_manifest() {
  format::Manifest m;
  m.tool_version = "test";
  m.x = Axis{"lon", AxisKind::kLongitude, "degrees_east", "", "", "", {0, 1, 2}};
  m.y = Axis{"lat", AxisKind::kLatitude, "degrees_north", "", "", "", {50, 51}};
  m.z = Axis{"height", AxisKind::kModelLevel, "1", "", "", "", {1, 2, 3, 4}};
  m.time = TimeAxis{"time", "hours since 2000-01-01", "standard", {0}};
  format::StoreVariable v;
  v.name = "ta";
  m.variables.push_back(v);
  m.brick = 4;
  format::GridGeometry g;
  g.vertical.kind = format::VerticalGeometry::Kind::kField;
  g.vertical.units = "m";
  g.vertical.formula = "atmosphere_hybrid_height_coordinate";
  g.vertical.terms = {{"a", "a"}, {"b", "b"}, {"orog", "topography_c"}};
  m.geometry = g;
  m.format_version = format::version_for_plan(m);
  m.store_id = format::compute_store_id(m);
  return m;
}

TEST(GeometryStoreRefusedTest, StoreWithAGridGeometryIsNotOpened) {
  const testing::TempDir dir;
  const format::Manifest m = hybrid_height_manifest();
  ASSERT_EQ(m.format_version, 5u);
  write_file_atomically(dir / "MANIFEST", format::encode_manifest(m));
  expect_error([&] { Store::open(dir.path()); }, ErrorCode::kUnsupported,
               {dir.path().string(), "grid geometry", "format version 5"});
}

}  // namespace
}  // namespace strielad
