// SPDX-License-Identifier: Apache-2.0
// Manifest version 5: the grid geometry record round-trips and is in the plan; writers use
// version 5 only with a geometry; readers reject geometry keys in older versions, a
// version 5 without one, and every geometry a writer cannot produce, naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

#include "format/manifest.h"
#include "support/expect_error.h"

namespace strielad::format {
namespace {

using testing::expect_error;
using Json = nlohmann::json;

Manifest base() {
  Manifest m;
  m.tool_version = "test";
  m.x = Axis{"west_east", AxisKind::kOther, "1", "", "", "", {0, 1, 2}};
  m.y = Axis{"south_north", AxisKind::kOther, "1", "", "", "", {0, 1}};
  m.z = Axis{"height", AxisKind::kModelLevel, "1", "", "", "", {1, 2, 3, 4}};
  m.time = TimeAxis{"time", "hours since 2000-01-01", "standard", {0, 1}};
  StoreVariable v;
  v.name = "ta";
  m.variables.push_back(v);
  m.brick = 4;
  return m;
}

Manifest sealed(Manifest m) {
  m.format_version = version_for_plan(m);
  m.store_id = compute_store_id(m);
  return m;
}

// A WRF-like grid: curvilinear, time-varying heights from PH and PHB, the terrain.
Manifest curvilinear_field() {
  Manifest m = base();
  m.x.kind = m.y.kind = AxisKind::kIndex;
  GridGeometry g;
  g.horizontal.kind = HorizontalGeometry::Kind::kCurvilinear;
  g.horizontal.lon_variable = "XLONG";
  g.horizontal.lat_variable = "XLAT";
  g.horizontal.coordinates_checksum = 0x0123456789abcdefull;
  g.vertical.kind = VerticalGeometry::Kind::kField;
  g.vertical.quantity = VerticalGeometry::Quantity::kHeight;
  g.vertical.units = "m";
  g.vertical.formula = std::string(kGeometryFormulaVariable);
  g.vertical.sources = {"PH", "PHB"};
  g.vertical.varies_in_time = true;
  g.vertical.dtype = DType::kFloat64;
  g.vertical.codec.predictor = "lorenzo3";
  g.vertical.codec.fpzip = true;
  g.surface = SurfaceGeometry{"HGT", "m"};
  g.orientation = -1;
  m.geometry = g;
  return sealed(m);
}

// An ICON-like grid: lon/lat axes, CF hybrid height, time-invariant.
Manifest hybrid_height() {
  Manifest m = base();
  m.x = Axis{"lon", AxisKind::kLongitude, "degrees_east", "", "", "", {0, 1, 2}};
  m.y = Axis{"lat", AxisKind::kLatitude, "degrees_north", "", "", "", {50, 51}};
  GridGeometry g;
  g.vertical.kind = VerticalGeometry::Kind::kField;
  g.vertical.units = "m";
  g.vertical.formula = "atmosphere_hybrid_height_coordinate";
  g.vertical.terms = {{"a", "a"}, {"b", "b"}, {"orog", "topography_c"}};
  m.geometry = g;
  return sealed(m);
}

// ln-pressure levels on a rotated grid (a grid mapping and a geometry together).
Manifest pressure_levels() {
  Manifest m = base();
  m.x = Axis{"rlon", AxisKind::kProjectionX, "degrees", "", "", "", {-1, 0, 1}};
  m.y = Axis{"rlat", AxisKind::kProjectionY, "degrees", "", "", "", {-1, 1}};
  GridMapping gm;
  gm.variable = "rotated_pole";
  gm.name = "rotated_latitude_longitude";
  gm.attributes = {{"grid_north_pole_latitude", 39.25}};
  gm.proj = "+proj=ob_tran";
  m.grid_mapping = gm;
  GridGeometry g;
  g.vertical.kind = VerticalGeometry::Kind::kLevels;
  g.vertical.quantity = VerticalGeometry::Quantity::kPressure;
  g.vertical.units = "Pa";
  g.vertical.formula = "atmosphere_ln_pressure_coordinate";
  g.vertical.levels = {100000, 85000, 50000, 1000.5};
  m.geometry = g;
  return sealed(m);
}

Manifest decode_edited(const Manifest& m, const std::function<void(Json&)>& edit) {
  Json j = manifest_to_json(m);
  edit(j);
  return manifest_from_json(j, "MANIFEST");
}

TEST(ManifestGeometryTest, RoundTripsEveryKindOfGeometry) {
  for (const Manifest& m : {curvilinear_field(), hybrid_height(), pressure_levels()}) {
    EXPECT_EQ(m.format_version, kManifestVersionGeometry);
    const Manifest back = decode_manifest(encode_manifest(m), "MANIFEST");
    ASSERT_TRUE(back.geometry.has_value());
    EXPECT_EQ(*back.geometry, *m.geometry);
    EXPECT_EQ(back.grid_mapping, m.grid_mapping);
    EXPECT_EQ(back.store_id, m.store_id);
    EXPECT_EQ(encode_manifest(back), encode_manifest(m));
  }
}

TEST(ManifestGeometryTest, GeometryIsPartOfThePlan) {
  Manifest a = curvilinear_field(), b = curvilinear_field();
  b.geometry->horizontal.coordinates_checksum ^= 1;
  EXPECT_NE(compute_store_id(a), compute_store_id(b));
  b = curvilinear_field();
  b.geometry->vertical.varies_in_time = false;
  EXPECT_NE(compute_store_id(a), compute_store_id(b));
  EXPECT_EQ(manifest_plan_json(a)["geometry"]["horizontal"]["coordinates_checksum"],
            "0123456789abcdef");
}

TEST(ManifestGeometryTest, GeometryDecidesTheStoreFilesAndStepSections) {
  const Manifest plain = sealed(base()), wrf = curvilinear_field(), icon = hybrid_height(),
                 levels = pressure_levels();
  EXPECT_EQ(step_section_count(plain), 1u);
  EXPECT_FALSE(has_geometry_file(plain));
  EXPECT_FALSE(has_geometry_bricks(plain));
  // Time-varying field: one more section per step file; coordinates and surface in GEOMETRY.
  EXPECT_EQ(step_section_count(wrf), 2u);
  EXPECT_TRUE(has_geometry_file(wrf));
  EXPECT_FALSE(has_geometry_bricks(wrf));
  // Time-invariant field: geometry.bricks; axes place x and y, no surface: no GEOMETRY.
  EXPECT_EQ(step_section_count(icon), 1u);
  EXPECT_FALSE(has_geometry_file(icon));
  EXPECT_TRUE(has_geometry_bricks(icon));
  // Levels: in the manifest only.
  EXPECT_EQ(step_section_count(levels), 1u);
  EXPECT_FALSE(has_geometry_file(levels));
  EXPECT_FALSE(has_geometry_bricks(levels));
}

TEST(ManifestGeometryTest, VersionFiveOnlyWithAGeometry) {
  Manifest m = base();
  EXPECT_FALSE(needs_geometry_version(m));
  EXPECT_EQ(version_for_plan(m), kManifestVersionPredictors);
  m.codec.fpzip = true;
  m.geometry = hybrid_height().geometry;
  EXPECT_TRUE(needs_geometry_version(m));
  EXPECT_EQ(version_for_plan(m), kManifestVersionGeometry);
  // A writer refuses a version that does not fit the content.
  Manifest four = curvilinear_field();
  four.format_version = kManifestVersionGeoreference;
  expect_error([&] { encode_manifest(four); }, ErrorCode::kInvalidArgument,
               {"a version 4 manifest cannot hold a grid geometry"});
  Manifest five = sealed(base());
  five.format_version = kManifestVersionGeometry;
  expect_error([&] { encode_manifest(five); }, ErrorCode::kInvalidArgument,
               {"a version 5 manifest needs a grid geometry"});
}

TEST(ManifestGeometryTest, WritersRefuseAGeometryReadersWouldReject) {
  Manifest m = curvilinear_field();
  m.geometry->horizontal.lat_variable.clear();
  expect_error([&] { compute_store_id(m); }, ErrorCode::kInvalidArgument,
               {"geometry.horizontal", "lat_variable"});
  Manifest p = pressure_levels();
  p.geometry->vertical.levels[2] = p.geometry->vertical.levels[1];
  expect_error([&] { encode_manifest(p); }, ErrorCode::kInvalidArgument,
               {"geometry.vertical.levels", "index 2"});
  Manifest nothing = sealed(base());
  nothing.geometry = GridGeometry{};
  nothing.format_version = kManifestVersionGeometry;
  expect_error([&] { encode_manifest(nothing); }, ErrorCode::kInvalidArgument,
               {"geometry places nothing"});
}

TEST(ManifestGeometryTest, ReadersRejectGeometryInOlderVersions) {
  const Json geometry = manifest_to_json(hybrid_height())["geometry"];
  for (int version : {1, 2, 3, 4}) {
    expect_error([&] {
      Manifest m = sealed(base());
      if (version == 4) {
        m.x.values = {0, 180, 360};
        m.x.kind = AxisKind::kLongitude;
        m.x.periodic = true;
        m = sealed(m);
      }
      decode_edited(m, [&](Json& j) {
        j["format_version"] = version;
        j["geometry"] = geometry;
      });
    }, ErrorCode::kCorrupt, {"MANIFEST", "'geometry' needs format version 5"});
  }
}

TEST(ManifestGeometryTest, ReadersRejectVersionFiveWithoutGeometry) {
  expect_error([] { decode_edited(hybrid_height(), [](Json& j) { j.erase("geometry"); }); },
               ErrorCode::kCorrupt, {"MANIFEST", "format version 5 but no key 'geometry'"});
}

TEST(ManifestGeometryTest, ReadersRejectVersionSevenAsTooNew) {
  std::vector<std::byte> bytes = encode_manifest(hybrid_height());
  bytes[8] = std::byte{7};
  expect_error([&] { decode_manifest(bytes, "MANIFEST"); }, ErrorCode::kVersionTooNew,
               {"MANIFEST", "version 7 is newer than this reader (max 6)"});
  expect_error([] { decode_edited(hybrid_height(), [](Json& j) { j["format_version"] = 7; }); },
               ErrorCode::kVersionTooNew, {"max 6"});
}

TEST(ManifestGeometryTest, ReadersRejectUnknownKindsAndQuantities) {
  expect_error([] {
    decode_edited(hybrid_height(), [](Json& j) { j["geometry"]["vertical"]["kind"] = "sigma"; });
  }, ErrorCode::kCorrupt, {"geometry.vertical", "unknown kind 'sigma'"});
  expect_error([] {
    decode_edited(hybrid_height(), [](Json& j) { j["geometry"]["vertical"]["quantity"] = "depth"; });
  }, ErrorCode::kCorrupt, {"geometry.vertical", "unknown quantity 'depth'"});
  expect_error([] {
    decode_edited(hybrid_height(), [](Json& j) { j["geometry"]["horizontal"]["kind"] = "mesh"; });
  }, ErrorCode::kCorrupt, {"geometry.horizontal", "unknown kind 'mesh'"});
  expect_error([] {
    decode_edited(hybrid_height(), [](Json& j) { j["geometry"]["vertical"]["units"] = "km"; });
  }, ErrorCode::kCorrupt, {"geometry.vertical", "units 'km' must be 'm'"});
  expect_error([] {
    decode_edited(hybrid_height(), [](Json& j) { j["geometry"]["vertical"]["dtype"] = "int8"; });
  }, ErrorCode::kCorrupt, {"geometry.vertical", "'dtype'"});
  expect_error([] {
    decode_edited(hybrid_height(), [](Json& j) { j["geometry"]["vertical"].erase("codec"); });
  }, ErrorCode::kCorrupt, {"geometry.vertical", "missing key 'codec'"});
  expect_error([] {
    decode_edited(hybrid_height(),
                  [](Json& j) { j["geometry"]["vertical"]["codec"]["predictor"] = "delta"; });
  }, ErrorCode::kCorrupt, {"geometry.vertical.codec", "predictor 'delta'"});
  expect_error([] {
    decode_edited(hybrid_height(), [](Json& j) { j["geometry"]["vertical"]["extra"] = 1; });
  }, ErrorCode::kCorrupt, {"geometry.vertical", "unknown key 'extra'"});
  expect_error([] {
    decode_edited(hybrid_height(), [](Json& j) { j["geometry"]["orientation"] = 0; });
  }, ErrorCode::kCorrupt, {"geometry.orientation 0"});
  expect_error([] {
    decode_edited(hybrid_height(), [](Json& j) { j["geometry"]["vertical"]["terms"] = Json::object(); });
  }, ErrorCode::kCorrupt, {"geometry.vertical", "no 'terms'"});
  expect_error([] {
    decode_edited(curvilinear_field(), [](Json& j) { j["geometry"]["vertical"]["sources"] = Json::array(); });
  }, ErrorCode::kCorrupt, {"geometry.vertical", "no 'sources'"});
}

TEST(ManifestGeometryTest, ReadersRejectBadLevels) {
  auto with_levels = [](Json levels) {
    decode_edited(pressure_levels(), [&](Json& j) { j["geometry"]["vertical"]["levels"] = levels; });
  };
  expect_error([&] { with_levels(Json{100000, 85000, 85000, 1000}); }, ErrorCode::kCorrupt,
               {"geometry.vertical.levels are not strictly monotonic at index 2"});
  expect_error([&] { with_levels(Json{100000, 85000, 90000, 1000}); }, ErrorCode::kCorrupt,
               {"not strictly monotonic at index 2"});
  expect_error([&] { with_levels(Json{100000, 85000, 50000}); }, ErrorCode::kCorrupt,
               {"geometry.vertical.levels has 3 values for a z axis of 4"});
  expect_error([&] { with_levels(Json{100000, 85000, std::nan(""), 1000}); }, ErrorCode::kCorrupt,
               {"geometry.vertical.levels[2] is not finite"});
  // Written out, a NaN is null (JSON has no NaN), which has the wrong type.
  expect_error([&] { with_levels(Json{100000, 85000, nullptr, 1000}); }, ErrorCode::kCorrupt,
               {"geometry.vertical", "'levels'"});
  Manifest m = pressure_levels();
  m.geometry->vertical.levels[1] = std::numeric_limits<double>::infinity();
  expect_error([&] { compute_store_id(m); }, ErrorCode::kInvalidArgument,
               {"geometry.vertical.levels[1] is not finite"});
}

TEST(ManifestGeometryTest, IndexAxesGoWithCurvilinearGridsOnly) {
  EXPECT_EQ(curvilinear_field().x.kind, AxisKind::kIndex);
  expect_error([] {
    decode_edited(curvilinear_field(), [](Json& j) { j["grid"]["y"]["kind"] = "other"; });
  }, ErrorCode::kCorrupt, {"MANIFEST", "index axes go with a curvilinear geometry.horizontal"});
  expect_error([] {
    decode_edited(hybrid_height(), [](Json& j) {
      j["grid"]["x"]["kind"] = "index";
      j["grid"]["y"]["kind"] = "index";
      j["grid"]["x"]["values"] = {0, 1, 2};
      j["grid"]["y"]["values"] = {0, 1};
    });
  }, ErrorCode::kCorrupt, {"axes x 'lon' (index)", "only with one"});
  expect_error([] {
    decode_edited(curvilinear_field(), [](Json& j) { j["grid"]["x"]["values"] = {0, 1, 3}; });
  }, ErrorCode::kCorrupt, {"index axis 'west_east' holds 3 at 2"});
  expect_error([] {
    decode_edited(curvilinear_field(), [](Json& j) { j["grid"]["z"]["kind"] = "index"; });
  }, ErrorCode::kCorrupt, {"grid.z 'height' has kind 'index'"});
  expect_error([] {
    decode_edited(curvilinear_field(), [](Json& j) {
      j["format_version"] = 4;
      j.erase("geometry");
    });
  }, ErrorCode::kCorrupt, {"axis kind 'index' needs format version 5"});
}

TEST(ManifestGeometryTest, ReadersRejectCurvilinearGridsWithoutNames) {
  expect_error([] {
    decode_edited(curvilinear_field(), [](Json& j) { j["geometry"]["horizontal"].erase("lon_variable"); });
  }, ErrorCode::kCorrupt, {"geometry.horizontal", "missing key 'lon_variable'"});
  expect_error([] {
    decode_edited(curvilinear_field(), [](Json& j) { j["geometry"]["horizontal"]["lat_variable"] = ""; });
  }, ErrorCode::kCorrupt, {"geometry.horizontal", "'lat_variable'"});
  expect_error([] {
    decode_edited(curvilinear_field(), [](Json& j) { j["geometry"]["horizontal"]["lat_variable"] = "XLONG"; });
  }, ErrorCode::kCorrupt, {"both 'XLONG'"});
  expect_error([] {
    decode_edited(curvilinear_field(),
                  [](Json& j) { j["geometry"]["horizontal"]["coordinates_checksum"] = "XYZ"; });
  }, ErrorCode::kCorrupt, {"geometry.horizontal", "coordinates_checksum"});
  expect_error([] {
    decode_edited(curvilinear_field(), [](Json& j) {
      j["grid"]["mapping"] = Json{{"variable", "lambert"}, {"grid_mapping_name", "lambert_conformal_conic"},
                                  {"attributes", Json::object()}, {"proj", ""}};
    });
  }, ErrorCode::kCorrupt, {"curvilinear but the grid has a mapping ('lambert')"});
}

}  // namespace
}  // namespace strielad::format
