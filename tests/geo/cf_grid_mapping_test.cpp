// SPDX-License-Identifier: Apache-2.0
// CF grid mappings placed by PROJ: each mapping's pipeline puts a point where PROJ's own
// cs2cs puts it with the classic definition of the same projection (expected values
// printed by `cs2cs -f %.10f <definition> +to +proj=longlat +ellps=WGS84`, proj-bin 9.1,
// not computed by this code), the inverse returns the axis coordinates, and attributes a
// mapping cannot be placed by are refused naming them.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <string>

#include "geo/cf_grid_mapping.h"
#include "geo/grid_projection.h"
#include "support/expect_error.h"

namespace strielad::geo {
namespace {

using nlohmann::json;
using strielad::testing::expect_error;

Axis axis(std::string name, std::string units) {
  Axis a;
  a.name = std::move(name);
  a.units = std::move(units);
  a.values = {0, 1};
  return a;
}

GridMapping mapping(std::string name, json attributes) {
  GridMapping m;
  m.variable = "crs";
  m.name = name;
  m.attributes = std::move(attributes);
  m.attributes["grid_mapping_name"] = name;
  return m;
}

struct Reference {
  const char* label;
  GridMapping mapping;
  const char* units;
  double x, y;      // axis coordinates
  double lon, lat;  // cs2cs
};

std::vector<Reference> references() {
  return {
      {"EUR-11 rotated pole, SW corner",
       mapping("rotated_latitude_longitude",
               {{"grid_north_pole_latitude", 39.25}, {"grid_north_pole_longitude", -162.0}}),
       "degrees", -28.375, -23.375, -10.0638796622, 21.9878287568},
      {"EUR-11 rotated pole, NE corner",
       mapping("rotated_latitude_longitude",
               {{"grid_north_pole_latitude", 39.25}, {"grid_north_pole_longitude", -162.0}}),
       "degrees", 18.155, 21.835, 64.9643766672, 66.6898365421},
      {"rotated pole with north_pole_grid_longitude",
       mapping("rotated_latitude_longitude", {{"grid_north_pole_latitude", 40.0},
                                              {"grid_north_pole_longitude", -350.0},
                                              {"north_pole_grid_longitude", 10.0}}),
       "degrees", 5, -3, -177.2986067700, 46.7559956598},
      {"Lambert conformal, sphere, two parallels, false origin",
       mapping("lambert_conformal_conic",
               {{"standard_parallel", json::array({30.0, 60.0})},
                {"latitude_of_projection_origin", 50.0},
                {"longitude_of_central_meridian", 10.0},
                {"false_easting", 1000.0},
                {"false_northing", -2000.0},
                {"earth_radius", 6371229.0}}),
       "m", 250000, -300000, 13.4114768433, 47.1793615362},
      {"Lambert conformal in km",
       mapping("lambert_conformal_conic",
               {{"standard_parallel", json::array({30.0, 60.0})},
                {"latitude_of_projection_origin", 50.0},
                {"longitude_of_central_meridian", 10.0},
                {"false_easting", 1000.0},
                {"false_northing", -2000.0},
                {"earth_radius", 6371229.0}}),
       "km", 250, -300, 13.4114768433, 47.1793615362},
      {"polar stereographic, standard parallel",
       mapping("polar_stereographic", {{"straight_vertical_longitude_from_pole", -105.0},
                                       {"latitude_of_projection_origin", 90.0},
                                       {"standard_parallel", 60.0}}),
       "m", -1000000, -2000000, -131.5650511771, 68.7804717722},
      {"transverse Mercator (UTM 32N)",
       mapping("transverse_mercator", {{"scale_factor_at_central_meridian", 0.9996},
                                       {"longitude_of_central_meridian", 9.0},
                                       {"latitude_of_projection_origin", 0.0},
                                       {"false_easting", 500000.0}}),
       "m", 600000, 5300000, 10.3365909749, 47.8455612525},
      {"Mercator, semi axes",
       mapping("mercator", {{"longitude_of_projection_origin", 0.0},
                            {"standard_parallel", 20.0},
                            {"semi_major_axis", 6378137.0},
                            {"semi_minor_axis", 6356752.314245}}),
       "m", 1000000, 2000000, 9.5559277880, 18.8845212432},
      {"Lambert azimuthal equal area (ETRS89-LAEA)",
       mapping("lambert_azimuthal_equal_area", {{"longitude_of_projection_origin", 10.0},
                                                {"latitude_of_projection_origin", 52.0},
                                                {"false_easting", 4321000.0},
                                                {"false_northing", 3210000.0},
                                                {"semi_major_axis", 6378137.0},
                                                {"inverse_flattening", 298.257222101}}),
       "m", 4000000, 3000000, 5.5177962124, 50.0241187585},
      {"Albers equal area (CONUS)",
       mapping("albers_conical_equal_area", {{"standard_parallel", json::array({29.5, 45.5})},
                                             {"latitude_of_projection_origin", 23.0},
                                             {"longitude_of_central_meridian", -96.0}}),
       "m", -500000, 1500000, -101.6307199398, 36.4146966233},
      {"azimuthal equidistant",
       mapping("azimuthal_equidistant", {{"longitude_of_projection_origin", -100.0},
                                         {"latitude_of_projection_origin", 45.0}}),
       "m", 300000, 200000, -96.0740380333, 46.7333181065},
      {"orthographic",
       mapping("orthographic", {{"longitude_of_projection_origin", -90.0},
                                {"latitude_of_projection_origin", 40.0}}),
       "m", 100000, -100000, -88.8440174048, 39.0934311680},
      {"Lambert cylindrical equal area",
       mapping("lambert_cylindrical_equal_area", {{"longitude_of_central_meridian", 0.0},
                                                  {"standard_parallel", 30.0}}),
       "m", 1000000, 1000000, 10.3641678112, 7.8626314321},
      {"sinusoidal", mapping("sinusoidal", {{"longitude_of_central_meridian", 10.0}}), "m", 500000,
       4000000, 15.5546210732, 36.1302929197},
      {"oblique stereographic, sphere, false origin",
       mapping("stereographic", {{"longitude_of_projection_origin", 10.0},
                                 {"latitude_of_projection_origin", 60.0},
                                 {"scale_factor_at_projection_origin", 0.99},
                                 {"false_easting", 100.0},
                                 {"false_northing", 200.0},
                                 {"earth_radius", 6370000.0}}),
       "m", 200000, -100000, 13.5316912047, 59.0414004306},
  };
}

TEST(CfGridMappingTest, PlacesPointsWhereCs2csDoes) {
  for (const Reference& r : references()) {
    const std::string proj =
        cf_grid_mapping_proj(r.mapping, axis("x", r.units), axis("y", r.units), "test");
    const GridProjection p(proj);
    const auto ll = p.to_geographic(r.x, r.y);
    EXPECT_NEAR(ll[0], r.lon, 1e-9) << r.label << ": " << proj;
    EXPECT_NEAR(ll[1], r.lat, 1e-9) << r.label << ": " << proj;
    const auto back = p.to_axis(ll[0], ll[1]);
    const double scale = std::max(1.0, std::fabs(r.x) + std::fabs(r.y));
    EXPECT_NEAR(back[0], r.x, 1e-9 * scale) << r.label;
    EXPECT_NEAR(back[1], r.y, 1e-9 * scale) << r.label;
  }
}

// Many points of the EUR-11 rotated grid against cs2cs itself, run now (skipped where
// proj-bin is not installed).
TEST(CfGridMappingTest, RotatedPoleAgreesWithCs2csOnAGridOfPoints) {
  if (std::system("command -v cs2cs >/dev/null 2>&1") != 0) GTEST_SKIP() << "cs2cs not installed";
  const GridMapping m = mapping("rotated_latitude_longitude", {{"grid_north_pole_latitude", 39.25},
                                                               {"grid_north_pole_longitude", -162.0}});
  const GridProjection p(cf_grid_mapping_proj(m, axis("rlon", "degrees"), axis("rlat", "degrees"), "t"));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> rlon(-28.375, 18.155), rlat(-23.375, 21.835);
  std::string input;
  std::vector<std::array<double, 2>> points;
  for (int i = 0; i < 200; ++i) {
    points.push_back({rlon(rng), rlat(rng)});
    input += fmt::format("{:.12f} {:.12f}\n", points.back()[0], points.back()[1]);
  }
  const std::string command =
      "printf '%s' '" + input +
      "' | cs2cs -f %.12f +proj=ob_tran +o_proj=longlat +o_lat_p=39.25 +o_lon_p=0 +lon_0=18 "
      "+to_meter=0.0174532925199433 +to +proj=longlat +ellps=WGS84";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  for (const auto& q : points) {
    double lon = 0, lat = 0, h = 0;
    ASSERT_EQ(std::fscanf(pipe, "%lf %lf %lf", &lon, &lat, &h), 3);
    const auto ll = p.to_geographic(q[0], q[1]);
    EXPECT_NEAR(ll[0], lon, 1e-9);
    EXPECT_NEAR(ll[1], lat, 1e-9);
  }
  pclose(pipe);
}

TEST(CfGridMappingTest, LatitudeLongitudeNeedsNoPipeline) {
  EXPECT_EQ(cf_grid_mapping_proj(mapping("latitude_longitude", {{"earth_radius", 6371229.0}}),
                                 axis("lon", "degrees_east"), axis("lat", "degrees_north"), "t"),
            "");
  const GridProjection identity("");
  EXPECT_TRUE(identity.identity());
  EXPECT_EQ(identity.to_geographic(12.5, -3.25), (std::array<double, 2>{12.5, -3.25}));
}

TEST(CfGridMappingTest, RefusesWhatItCannotPlace) {
  const Axis m = axis("x", "m"), deg = axis("rlon", "degrees");
  expect_error([&] { cf_grid_mapping_proj(mapping("geostationary", {}), m, m, "f.nc: variable 'T'"); },
               ErrorCode::kUnsupported,
               {"f.nc: variable 'T'", "'crs'", "geostationary", "lambert_conformal_conic"});
  expect_error([&] {
    cf_grid_mapping_proj(mapping("lambert_conformal_conic", {{"standard_parallel", 30.0},
                                                             {"latitude_of_projection_origin", 40.0}}),
                         m, m, "t");
  }, ErrorCode::kInvalidInput, {"lacks the attribute 'longitude_of_central_meridian'"});
  expect_error([&] {
    cf_grid_mapping_proj(mapping("rotated_latitude_longitude", {{"grid_north_pole_latitude", 95.0},
                                                                {"grid_north_pole_longitude", 0.0}}),
                         deg, deg, "t");
  }, ErrorCode::kInvalidInput, {"grid_north_pole_latitude", "95", "not a latitude"});
  expect_error([&] {
    cf_grid_mapping_proj(mapping("rotated_latitude_longitude", {{"grid_north_pole_latitude", 40.0},
                                                                {"grid_north_pole_longitude", 0.0}}),
                         m, m, "t");
  }, ErrorCode::kUnsupported, {"axis 'x' has units 'm'", "needs degrees"});
  expect_error([&] {
    cf_grid_mapping_proj(mapping("transverse_mercator", {{"scale_factor_at_central_meridian", 1.0},
                                                         {"longitude_of_central_meridian", 9.0},
                                                         {"latitude_of_projection_origin", 0.0}}),
                         deg, deg, "t");
  }, ErrorCode::kUnsupported, {"needs a length"});
  expect_error([&] {
    cf_grid_mapping_proj(mapping("mercator", {{"longitude_of_projection_origin", 0.0},
                                              {"standard_parallel", 10.0},
                                              {"scale_factor_at_projection_origin", 1.0}}),
                         m, m, "t");
  }, ErrorCode::kInvalidInput, {"both 'standard_parallel' and 'scale_factor_at_projection_origin'"});
  expect_error([&] {
    cf_grid_mapping_proj(mapping("polar_stereographic", {{"straight_vertical_longitude_from_pole", 0.0},
                                                         {"latitude_of_projection_origin", 60.0},
                                                         {"standard_parallel", 60.0}}),
                         m, m, "t");
  }, ErrorCode::kInvalidInput, {"+90 or -90"});
  expect_error([&] {
    cf_grid_mapping_proj(mapping("lambert_azimuthal_equal_area", {{"longitude_of_projection_origin", "ten"},
                                                                  {"latitude_of_projection_origin", 50.0}}),
                         m, m, "t");
  }, ErrorCode::kInvalidInput, {"'longitude_of_projection_origin' is not a number"});
  expect_error([&] {
    cf_grid_mapping_proj(mapping("sinusoidal", {{"longitude_of_central_meridian", 0.0},
                                                {"semi_minor_axis", 6356752.0}}),
                         m, m, "t");
  }, ErrorCode::kInvalidInput, {"'semi_minor_axis' without 'semi_major_axis'"});
}

TEST(CfGridMappingTest, PointsOutsideTheProjectionHaveNoPosition) {
  // Orthographic: only one hemisphere is visible; beyond the disc there is no point.
  const GridMapping ortho = mapping("orthographic", {{"longitude_of_projection_origin", 0.0},
                                                     {"latitude_of_projection_origin", 0.0}});
  const GridProjection p(cf_grid_mapping_proj(ortho, axis("x", "m"), axis("y", "m"), "t"));
  const auto ll = p.to_geographic(2e7, 0);
  EXPECT_TRUE(std::isnan(ll[0]) && std::isnan(ll[1]));
}

}  // namespace
}  // namespace strielad::geo
