// SPDX-License-Identifier: Apache-2.0
// Scene format 3's geographic box, and longitude ranges in any convention: parsing,
// the canonical form, what a reader rejects, and resolution against grids on longitude
// and latitude, on a rotated pole and without a place on the Earth.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "format/manifest.h"
#include "scene/scene.h"
#include "support/expect_error.h"

namespace strielad {
namespace {

using testing::expect_error;
constexpr double kInf = std::numeric_limits<double>::infinity();

format::Manifest lonlat(std::vector<double> lon) {
  format::Manifest m;
  m.x = Axis{"lon", AxisKind::kLongitude, "degrees_east", "longitude", "", "", std::move(lon)};
  m.y = Axis{"lat", AxisKind::kLatitude, "degrees_north", "latitude", "", "", {47.5, 51.0, 54.5}};
  m.z = Axis{"height", AxisKind::kHeight, "m", "height", "", "up", {20.0, 5000.0}};
  m.time = TimeAxis{"time", "", "", {0}};
  format::StoreVariable v;
  v.name = "ta";
  m.variables.push_back(v);
  return m;
}

format::Manifest rotated() {
  format::Manifest m = lonlat({0, 1});
  m.x = Axis{"rlon", AxisKind::kProjectionX, "degrees", "grid_longitude", "", "", {-10, 0, 10}};
  m.y = Axis{"rlat", AxisKind::kProjectionY, "degrees", "grid_latitude", "", "", {-10, 0, 10}};
  m.grid_mapping = GridMapping{"rotated_pole", "rotated_latitude_longitude", {}, "+proj=noop"};
  return m;
}

ResolvedScene resolve(const std::string& json, const format::Manifest& m) {
  return resolve_scene(parse_scene(json, "s.json"), m, "s.json");
}

TEST(GeographicBoxTest, ParsesAndWritesTheCanonicalForm) {
  const Scene s = parse_scene(R"({"format_version": 3, "subvolumes": [
      {"id": 1, "geographic": {"lat": [45, 55], "lon": [-10, 30]}}]})", "s.json");
  ASSERT_TRUE(s.subvolumes[0].geographic.has_value());
  EXPECT_EQ(s.subvolumes[0].geographic->lon, (AxisRange{-10, 30}));
  EXPECT_EQ(s.subvolumes[0].geographic->lat, (AxisRange{45, 55}));
  EXPECT_EQ(s.required_format_version(), kSceneVersionGeographicBox);
  const std::string canonical = scene_to_json(s);
  EXPECT_NE(canonical.find(R"("geographic":{"lon":[-10.0,30.0],"lat":[45.0,55.0]})"), std::string::npos)
      << canonical;
  EXPECT_EQ(parse_scene(canonical, "c"), s);
  EXPECT_EQ(scene_to_json(parse_scene(canonical, "c")), canonical);
}

TEST(GeographicBoxTest, ReadersRejectWhatItCannotMean) {
  expect_error([] { parse_scene(R"({"format_version": 2, "subvolumes": [{"id": 1, "geographic": {"lat": [0, 1]}}]})", "s.json"); },
               ErrorCode::kInvalidInput, {"s.json: subvolumes[0].geographic: was added in format_version 3"});
  expect_error([] { parse_scene(R"({"format_version": 3, "subvolumes": [{"id": 1, "geographic": {}}]})", "s.json"); },
               ErrorCode::kInvalidInput, {"subvolumes[0].geographic: needs at least one of 'lon', 'lat' and 'height'"});
  expect_error([] { parse_scene(R"({"format_version": 3, "subvolumes": [{"id": 1, "geographic": {"lat": [80, 95]}}]})", "s.json"); },
               ErrorCode::kInvalidInput, {"subvolumes[0].geographic.lat: [80, 95] is not within [-90, 90]"});
  expect_error([] { parse_scene(R"({"format_version": 3, "subvolumes": [{"id": 1, "geographic": {"lon": [30, 10]}}]})", "s.json"); },
               ErrorCode::kInvalidInput, {"subvolumes[0].geographic.lon: lo 30 is greater than hi 10"});
  expect_error([] { parse_scene(R"({"format_version": 3, "subvolumes": [{"id": 1, "geographic": {"height": [0, 1]}}]})", "s.json"); },
               ErrorCode::kInvalidInput, {"subvolumes[0].geographic.height: was added in format_version 4"});
  expect_error([] { parse_scene(R"({"format_version": 4, "subvolumes": [{"id": 1, "geographic": {"height": [5000, 1000]}}]})", "s.json"); },
               ErrorCode::kInvalidInput, {"subvolumes[0].geographic.height: lo 5000 is greater than hi 1000"});
  expect_error([] { parse_scene(R"({"format_version": 4, "subvolumes": [{"id": 1, "geographic": {"depth": [0, 1]}}]})", "s.json"); },
               ErrorCode::kInvalidInput, {"unknown key 'depth'", "lon, lat, height"});
}

TEST(GeographicBoxTest, HeightRangeNeedsFormatFourAndRoundTrips) {
  const Scene s = parse_scene(R"({"format_version": 4, "subvolumes": [
      {"id": 1, "geographic": {"height": [1000, 3000]}},
      {"id": 2, "geographic": {"lat": [45, 55]}}]})", "s.json");
  ASSERT_TRUE(s.subvolumes[0].geographic.has_value());
  EXPECT_EQ(s.subvolumes[0].geographic->height, (AxisRange{1000, 3000}));
  EXPECT_FALSE(s.subvolumes[0].geographic->lon.has_value());
  EXPECT_EQ(s.required_format_version(), kSceneVersionGeographicHeight);
  const std::string canonical = scene_to_json(s);
  EXPECT_NE(canonical.find(R"("geographic":{"height":[1000.0,3000.0]})"), std::string::npos)
      << canonical;
  EXPECT_NE(canonical.find(R"("format_version":4)"), std::string::npos) << canonical;
  EXPECT_EQ(parse_scene(canonical, "c"), s);
  // Without a height the lowest version that has every key stays 3.
  Scene lat_only = s;
  lat_only.subvolumes.erase(lat_only.subvolumes.begin());
  EXPECT_EQ(lat_only.required_format_version(), kSceneVersionGeographicBox);
}

TEST(GeographicBoxTest, HeightRangeIsTheHeightAxisRangeOnAHeightAxis) {
  const ResolvedScene r = resolve(R"({"format_version": 4, "subvolumes": [
      {"id": 1, "geographic": {"height": [1000, 3000], "lat": [47, 52]}}]})", lonlat({0, 1}));
  EXPECT_EQ(r.subvolumes[0].box[2], (AxisRange{1000, 3000}));
  EXPECT_EQ(r.subvolumes[0].box[1], (AxisRange{47, 52}));
  EXPECT_FALSE(r.subvolumes[0].geometry_height.has_value());
  expect_error([] { resolve(R"({"format_version": 4, "subvolumes": [
      {"id": 1, "domain": {"height": [100, 200]}, "geographic": {"height": [1000, 3000]}}]})", lonlat({0, 1})); },
               ErrorCode::kInvalidInput, {"subvolumes[0].geographic.height: the store's axis 'height' is the height already bounded"});
  expect_error([] { resolve(R"({"format_version": 4, "subvolumes": [
      {"id": 1, "geographic": {"height": [6000, 9000]}}]})", lonlat({0, 1})); },
               ErrorCode::kInvalidInput, {"subvolumes[0].geographic.height: [6000, 9000] lies outside the store's heights [20, 5000]"});
}

TEST(GeographicBoxTest, HeightRangeOnTerrainFollowingLevelsIsEvaluatedOnTheGeometryField) {
  format::Manifest m = lonlat({0, 1});
  m.z = Axis{"level", AxisKind::kModelLevel, "1", "model_level_number", "", "", {1, 2, 3}};
  format::GridGeometry g;
  g.vertical.kind = format::VerticalGeometry::Kind::kField;
  g.vertical.quantity = format::VerticalGeometry::Quantity::kHeight;
  g.vertical.units = "m";
  m.geometry = g;
  const ResolvedScene r = resolve(R"({"format_version": 4, "subvolumes": [
      {"id": 1, "geographic": {"height": [1000, 3000]}}]})", m);
  EXPECT_EQ(r.subvolumes[0].geometry_height, (AxisRange{1000, 3000}));
  EXPECT_EQ(r.subvolumes[0].box[2], (AxisRange{-kInf, kInf}));
  // The geometry field is read wherever the range is evaluated.
  EXPECT_NE(std::find(r.needed_variables.begin(), r.needed_variables.end(), 1u), r.needed_variables.end());

  // Levels placed by pressure have no heights to bound: refused, pointing at the field.
  m.geometry->vertical.quantity = format::VerticalGeometry::Quantity::kPressure;
  m.geometry->vertical.units = "Pa";
  expect_error([&] { resolve(R"({"format_version": 4, "subvolumes": [
      {"id": 1, "geographic": {"height": [1000, 3000]}}]})", m); },
               ErrorCode::kInvalidInput, {"subvolumes[0].geographic.height: the store's levels have no height",
                                          "'geometry_pressure'"});
  // So have pressure levels.
  format::Manifest p = lonlat({0, 1});
  p.z = Axis{"plev", AxisKind::kPressure, "Pa", "air_pressure", "", "down", {85000, 50000}};
  expect_error([&] { resolve(R"({"format_version": 4, "subvolumes": [
      {"id": 1, "geographic": {"height": [1000, 3000]}}]})", p); },
               ErrorCode::kInvalidInput, {"axis 'plev' is not a height"});
}

TEST(LongitudeRangesTest, AnyConventionMeansTheSameLongitudes) {
  const format::Manifest m = lonlat({4.5, 9.5, 14.5});
  // 364.5 .. 368 is 4.5 .. 8 east a turn on: kept as written, extraction shifts it.
  EXPECT_EQ(resolve(R"({"subvolumes": [{"id": 1, "domain": {"lon": [364.5, 368]}}]})", m)
                .subvolumes[0].box[0],
            (AxisRange{364.5, 368}));
  EXPECT_EQ(resolve(R"({"subvolumes": [{"id": 1, "domain": {"lon": [-355.5, -352]}}]})", m)
                .subvolumes[0].box[0],
            (AxisRange{-355.5, -352}));
  // A full turn or more is the whole axis.
  EXPECT_EQ(resolve(R"({"subvolumes": [{"id": 1, "domain": {"lon": [-180, 180]}}]})", m)
                .subvolumes[0].box[0],
            (AxisRange{-kInf, kInf}));
  // A range no turn brings onto the grid is an error that names it.
  expect_error([&] { resolve(R"({"subvolumes": [{"id": 1, "domain": {"lon": [100, 120]}}]})", m); },
               ErrorCode::kInvalidInput,
               {"s.json: subvolumes[0].domain.lon: [100, 120] selects no longitude of the store's lon axis [4.5, 14.5]"});
  // A meridian slice in the other convention is the grid's own meridian.
  const ResolvedScene slice = resolve(R"({"format_version": 2, "subvolumes": [{"id": 1, "limits": [{"var": "ta", "min": 0}]}],
      "slices": [{"id": 1, "axis": "lon", "value": -350.5, "var": "ta"}]})", m);
  EXPECT_EQ(slice.slices[0].value, 9.5);
}

TEST(GeographicBoxTest, OnALonLatGridItIsTheAxisBox) {
  const format::Manifest m = lonlat({4.5, 9.5, 14.5});
  const ResolvedSubVolume r = resolve(R"({"format_version": 3, "subvolumes": [
      {"id": 1, "geographic": {"lon": [365, 370], "lat": [48, 50]}}]})", m).subvolumes[0];
  EXPECT_EQ(r.box[0], (AxisRange{365, 370}));
  EXPECT_EQ(r.box[1], (AxisRange{48, 50}));
  EXPECT_FALSE(r.geographic.has_value());
  expect_error([&] {
    resolve(R"({"format_version": 3, "subvolumes": [{"id": 1, "domain": {"lon": [5, 6]},
        "geographic": {"lon": [5, 6]}}]})", m);
  }, ErrorCode::kInvalidInput, {"subvolumes[0].geographic.lon", "give the range once"});
  expect_error([&] {
    resolve(R"({"format_version": 3, "subvolumes": [{"id": 1, "geographic": {"lat": [60, 70]}}]})", m);
  }, ErrorCode::kInvalidInput, {"subvolumes[0].geographic.lat: [60, 70] lies outside the store's latitudes"});
}

TEST(GeographicBoxTest, OnAMappedGridItIsKeptForTheSamples) {
  const ResolvedSubVolume r = resolve(R"({"format_version": 3, "subvolumes": [
      {"id": 1, "geographic": {"lon": [0, 20], "lat": [45, 55]}}]})", rotated()).subvolumes[0];
  ASSERT_TRUE(r.geographic.has_value());
  EXPECT_EQ(r.geographic->lon, (AxisRange{0, 20}));
  EXPECT_EQ(r.box[0], (AxisRange{-kInf, kInf}));
}

TEST(GeographicBoxTest, AGridWithoutAPlaceOnTheEarthRefusesIt) {
  format::Manifest m = rotated();
  m.grid_mapping.reset();
  m.x.units = m.y.units = "m";
  expect_error([&] {
    resolve(R"({"format_version": 3, "subvolumes": [{"id": 1, "geographic": {"lat": [0, 1]}}]})", m);
  }, ErrorCode::kInvalidInput, {"subvolumes[0].geographic", "no place on the Earth"});
}

}  // namespace
}  // namespace strielad
