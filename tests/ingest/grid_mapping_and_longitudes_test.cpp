// SPDX-License-Identifier: Apache-2.0
// How the scanner places horizontal axes: CF grid mappings (a real EURO-CORDEX rotated
// pole, a Lambert grid in km) recorded with their PROJ pipeline, rotated coordinates
// without a mapping refused, Cartesian grids kept as such, longitudes round the Earth made
// periodic with the first meridian repeated, and coordinate variables named unlike their
// dimension paired with it (a real T42 file).
#include <gtest/gtest.h>

#include <cmath>

#include "convert/converter.h"
#include "geo/grid_projection.h"
#include "ingest/input_catalog.h"
#include "store/store.h"
#include "support/expect_error.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using strielad::testing::expect_error;
using strielad::testing::NcAttr;
using strielad::testing::NetcdfFixture;
using strielad::testing::ramp;
using strielad::testing::TempDir;

std::filesystem::path eur11() { return strielad::testing::ncarg_file("nug/tas_rotated_grid_EUR11.nc"); }

TEST(GridMappingAndLongitudesTest, RotatedPoleOfARealFileIsPlacedByProj) {
  if (!std::filesystem::exists(eur11())) GTEST_SKIP() << "libncarg-data not installed";
  const InputCatalog c = scan_inputs({eur11()}, {});
  EXPECT_EQ(c.x.kind, AxisKind::kProjectionX);
  EXPECT_EQ(c.y.kind, AxisKind::kProjectionY);
  EXPECT_FALSE(c.x.periodic);
  ASSERT_TRUE(c.grid_mapping.has_value());
  EXPECT_EQ(c.grid_mapping->variable, "rotated_pole");
  EXPECT_EQ(c.grid_mapping->name, "rotated_latitude_longitude");
  EXPECT_EQ(c.grid_mapping->attributes.at("grid_north_pole_latitude"), 39.25);
  EXPECT_EQ(c.grid_mapping->attributes.at("grid_north_pole_longitude"), -162.0);
  // The grid's first sample (rlon -28.375, rlat -23.375) lies where cs2cs puts it
  // (cs2cs +proj=ob_tran +o_proj=longlat +o_lat_p=39.25 +lon_0=18 ...): off the coast of
  // West Africa, not at 28.4 W 23.4 S.
  const geo::GridProjection p(c.grid_mapping->proj);
  const auto ll = p.to_geographic(c.x.values.front(), c.y.values.front());
  EXPECT_NEAR(ll[0], -10.0638796622, 1e-9);
  EXPECT_NEAR(ll[1], 21.9878287568, 1e-9);
}

TEST(GridMappingAndLongitudesTest, TheStoreRecordsTheMapping) {
  if (!std::filesystem::exists(eur11())) GTEST_SKIP() << "libncarg-data not installed";
  TempDir dir;
  build::ConvertOptions o;
  o.inputs = {eur11()};
  o.store = dir / "store";
  o.brick = 16;
  build::convert(o);
  const auto store = Store::open(o.store);
  const format::Manifest& m = store->manifest();
  EXPECT_EQ(m.format_version, format::kManifestVersionGeoreference);
  ASSERT_TRUE(m.grid_mapping.has_value());
  EXPECT_EQ(m.grid_mapping->name, "rotated_latitude_longitude");
  EXPECT_NE(m.grid_mapping->proj.find("+o_lat_p=39.25"), std::string::npos) << m.grid_mapping->proj;
  EXPECT_NE(m.grid_mapping->proj.find("+lon_0=18"), std::string::npos) << m.grid_mapping->proj;
  EXPECT_EQ(m.x.kind, AxisKind::kProjectionX);
}

// A Lambert conformal grid in km, as WRF-like tools write it with a CF mapping.
void write_lambert(const std::filesystem::path& path, std::string mapping_name = "lambert_conformal_conic",
                   std::string grid_mapping_attribute = "Lambert_Conformal") {
  NetcdfFixture()
      .coordinate("lev", {1000, 850}, {NcAttr::text_value("units", "hPa")})
      .coordinate("y", ramp(5, -200, 100),
                  {NcAttr::text_value("standard_name", "projection_y_coordinate"),
                   NcAttr::text_value("units", "km")})
      .coordinate("x", ramp(6, -250, 100),
                  {NcAttr::text_value("standard_name", "projection_x_coordinate"),
                   NcAttr::text_value("units", "km")})
      .variable("Lambert_Conformal", NC_INT, {}, {},
                {NcAttr::text_value("grid_mapping_name", mapping_name),
                 NcAttr::number("standard_parallel", NC_DOUBLE, {30.0, 60.0}),
                 NcAttr::number("longitude_of_central_meridian", NC_DOUBLE, {10.0}),
                 NcAttr::number("latitude_of_projection_origin", NC_DOUBLE, {50.0}),
                 NcAttr::number("earth_radius", NC_DOUBLE, {6371229.0})})
      .variable("T", NC_FLOAT, {"lev", "y", "x"}, ramp(60, 250),
                {NcAttr::text_value("grid_mapping", grid_mapping_attribute)})
      .write(path);
}

TEST(GridMappingAndLongitudesTest, LambertGridInKilometres) {
  TempDir dir;
  write_lambert(dir / "lcc.nc");
  const InputCatalog c = scan_inputs({dir / "lcc.nc"}, {});
  ASSERT_TRUE(c.grid_mapping.has_value());
  EXPECT_EQ(c.grid_mapping->attributes.at("standard_parallel"), (nlohmann::json::array({30.0, 60.0})));
  // cs2cs +proj=lcc +lat_1=30 +lat_2=60 +lat_0=50 +lon_0=10 +R=6371229 of (50 km, 100 km).
  const geo::GridProjection p(c.grid_mapping->proj);
  const auto ll = p.to_geographic(50, 100);
  const auto ref = [] {
    const geo::GridProjection classic(
        "+proj=pipeline +step +inv +proj=lcc +lat_1=30 +lat_2=60 +lat_0=50 +lon_0=10 +R=6371229 "
        "+step +proj=unitconvert +xy_in=rad +xy_out=deg");
    return classic.to_geographic(50000, 100000);
  }();
  EXPECT_NEAR(ll[0], ref[0], 1e-10);
  EXPECT_NEAR(ll[1], ref[1], 1e-10);
}

TEST(GridMappingAndLongitudesTest, ExtendedGridMappingFormNamesTheVariable) {
  TempDir dir;
  write_lambert(dir / "lcc.nc", "lambert_conformal_conic", "Lambert_Conformal: x y");
  const InputCatalog c = scan_inputs({dir / "lcc.nc"}, {});
  ASSERT_TRUE(c.grid_mapping.has_value());
  EXPECT_EQ(c.grid_mapping->variable, "Lambert_Conformal");
}

TEST(GridMappingAndLongitudesTest, BadMappingsAreRefusedNamingThem) {
  TempDir dir;
  ScanOptions named;
  named.variables = {"T"};
  write_lambert(dir / "a.nc", "lambert_conformal_conic", "crs");
  expect_error([&] { scan_inputs({dir / "a.nc"}, named); }, ErrorCode::kInvalidInput,
               {"a.nc: variable 'T'", "grid_mapping names 'crs', which is not a variable"});
  write_lambert(dir / "b.nc", "space_view");
  expect_error([&] { scan_inputs({dir / "b.nc"}, named); }, ErrorCode::kUnsupported,
               {"b.nc: variable 'T'", "'Lambert_Conformal'", "space_view", "rotated_latitude_longitude"});
}

TEST(GridMappingAndLongitudesTest, RotatedCoordinatesWithoutAMappingAreRefused) {
  TempDir dir;
  NetcdfFixture()
      .coordinate("lev", {1000, 850}, {NcAttr::text_value("units", "hPa")})
      .coordinate("rlat", ramp(3, -1, 1), {NcAttr::text_value("standard_name", "grid_latitude"),
                                            NcAttr::text_value("units", "degrees")})
      .coordinate("rlon", ramp(4, -2, 1), {NcAttr::text_value("standard_name", "grid_longitude"),
                                            NcAttr::text_value("units", "degrees")})
      .variable("T", NC_FLOAT, {"lev", "rlat", "rlon"}, ramp(24))
      .write(dir / "r.nc");
  ScanOptions named;
  named.variables = {"T"};
  expect_error([&] { scan_inputs({dir / "r.nc"}, named); }, ErrorCode::kInvalidInput,
               {"r.nc: variable 'T'", "'rlon' and 'rlat' are rotated-pole coordinates",
                "no grid_mapping attribute"});
}

TEST(GridMappingAndLongitudesTest, ProjectionCoordinatesWithoutAMappingAreACartesianGrid) {
  TempDir dir;
  NetcdfFixture()
      .coordinate("z", {0, 100}, {NcAttr::text_value("units", "m"), NcAttr::text_value("positive", "up")})
      .coordinate("y", ramp(3, 0, 50), {NcAttr::text_value("axis", "Y"), NcAttr::text_value("units", "m")})
      .coordinate("x", ramp(4, 0, 50), {NcAttr::text_value("axis", "X"), NcAttr::text_value("units", "m")})
      .variable("w", NC_FLOAT, {"z", "y", "x"}, ramp(24))
      .write(dir / "les.nc");
  const InputCatalog c = scan_inputs({dir / "les.nc"}, {});
  EXPECT_EQ(c.x.kind, AxisKind::kProjectionX);  // metres, never read as degrees
  EXPECT_EQ(c.y.kind, AxisKind::kProjectionY);
  EXPECT_FALSE(c.grid_mapping.has_value());
}

InputCatalog scan_longitudes(const TempDir& dir, const std::vector<double>& lon) {
  strielad::testing::SimpleGrid g;
  g.lon = lon;
  NetcdfFixture().grid(g).variable("T", NC_FLOAT, g.dims(), ramp(g.samples())).write(dir / "g.nc");
  return scan_inputs({dir / "g.nc"}, {});
}

TEST(GridMappingAndLongitudesTest, LongitudesRoundTheEarthArePeriodic) {
  TempDir dir;
  {
    const InputCatalog c = scan_longitudes(dir, ramp(144, 0, 2.5));  // 0 .. 357.5
    EXPECT_TRUE(c.x.periodic);
    EXPECT_EQ(c.x.size(), 145u);
    EXPECT_EQ(c.x.values.back(), 360.0);
    EXPECT_EQ(c.source_nx, 144u);
  }
  {
    const InputCatalog c = scan_longitudes(dir, ramp(144, -180, 2.5));  // -180 .. 177.5
    EXPECT_TRUE(c.x.periodic);
    EXPECT_EQ(c.x.values.back(), 180.0);
  }
  {
    const InputCatalog c = scan_longitudes(dir, ramp(145, 0, 2.5));  // 0 .. 360 repeated already
    EXPECT_TRUE(c.x.periodic);
    EXPECT_EQ(c.x.size(), 145u);
    EXPECT_EQ(c.source_nx, 145u);
  }
  {
    const InputCatalog c = scan_longitudes(dir, ramp(144, 357.5, -2.5));  // descending
    EXPECT_TRUE(c.x.periodic);
    EXPECT_EQ(c.x.values.back(), -2.5);
  }
  {
    const InputCatalog c = scan_longitudes(dir, ramp(140, 0, 2.5));  // stops 12.5 short
    EXPECT_FALSE(c.x.periodic);
    EXPECT_EQ(c.x.size(), 140u);
  }
}

TEST(GridMappingAndLongitudesTest, ThePeriodicColumnRepeatsTheFirstInTheStore) {
  TempDir dir;
  strielad::testing::SimpleGrid g;
  g.lon = ramp(8, 0, 45);  // 0 .. 315
  const auto data = ramp(g.samples(), 1);
  NetcdfFixture().grid(g).variable("T", NC_FLOAT, g.dims(), data).write(dir / "g.nc");
  build::ConvertOptions o;
  o.inputs = {dir / "g.nc"};
  o.store = dir / "store";
  o.brick = 4;
  build::convert(o);
  const auto store = Store::open(o.store);
  EXPECT_TRUE(store->manifest().x.periodic);
  EXPECT_EQ(store->manifest().format_version, format::kManifestVersionGeoreference);
  const auto expected = strielad::testing::with_repeated_first_column(data, 8);
  const OctreeLayout& octree = store->octree();
  for (NodeId n = 0; n < octree.level(0).node_count(); ++n) {
    const Brick b = store->read_brick(0, 0, n);
    for (std::size_t z = 0; z < b.dims[2]; ++z)
      for (std::size_t y = 0; y < b.dims[1]; ++y)
        for (std::size_t x = 0; x < b.dims[0]; ++x) {
          const double want = expected[((b.box.lo[2] + z) * 3 + b.box.lo[1] + y) * 9 + b.box.lo[0] + x];
          ASSERT_EQ(b.sample((z * b.dims[1] + y) * b.dims[0] + x), want) << n;
        }
  }
}

TEST(GridMappingAndLongitudesTest, CoordinatesNamedUnlikeTheirDimensionArePaired) {
  const auto file = strielad::testing::ncarg_file("cdf/ex01B1_uv300.hs.nc");
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "libncarg-data not installed";
  // lon(longitude), lat(latitude), plvl(level): T42 Gaussian latitudes, 0..360 longitudes.
  const InputCatalog c = scan_inputs({file}, {});
  EXPECT_EQ(c.x.name, "lon");
  EXPECT_EQ(c.y.name, "lat");
  EXPECT_EQ(c.z.name, "plvl");
  EXPECT_EQ(c.z.kind, AxisKind::kPressure);
  EXPECT_EQ(c.dims(), (Dims3{129, 64, 1}));
  EXPECT_TRUE(c.x.periodic);  // the file repeats the first meridian itself
  EXPECT_EQ(c.source_nx, 129u);
  // Gaussian latitudes: kept as stored, not resampled.
  EXPECT_NEAR(c.y.values.front(), -87.8638, 1e-4);
}

TEST(GridMappingAndLongitudesTest, TwoCandidateCoordinatesPairNothing) {
  TempDir dir;
  NetcdfFixture()
      .coordinate("lev", {1000, 850}, {NcAttr::text_value("units", "hPa")})
      .coordinate("lat", ramp(3, -1, 1), {NcAttr::text_value("units", "degrees_north")})
      .dimension("longitude", 4)
      .variable("lon", NC_DOUBLE, {"longitude"}, ramp(4, 0, 1), {NcAttr::text_value("units", "degrees_east")})
      .variable("lon_b", NC_DOUBLE, {"longitude"}, ramp(4, 0.5, 1), {NcAttr::text_value("units", "degrees_east")})
      .variable("T", NC_FLOAT, {"lev", "lat", "longitude"}, ramp(24))
      .write(dir / "two.nc");
  ScanOptions named;
  named.variables = {"T"};
  expect_error([&] { scan_inputs({dir / "two.nc"}, named); }, ErrorCode::kInvalidInput,
               {"two.nc", "dimension 'longitude' has no coordinate variable",
                "2 1-D variables over it could be one (lon, lon_b)", "ncrename -v lon,longitude"});
}

}  // namespace
}  // namespace strielad::ingest
