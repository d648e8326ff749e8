// SPDX-License-Identifier: Apache-2.0
// GRIB grids become the axes and CF grid mapping a netCDF input would give, checked
// sample by sample against the latitudes and longitudes ecCodes itself computes for the
// message: NCEP's Lambert AWIPS 211 grid and a COSMO-DE rotated grid (libncarg-data),
// and ecCodes' own regular, Gaussian and rotated templates in GRIB 1 and 2 (its polar
// stereographic templates are placeholders: true latitude 0, Dx 0). What is not a
// regular grid is refused with what to do.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include "geo/grid_projection.h"
#include "ingest/grib_grid.h"
#include "ingest/grib_messages.h"
#include "support/expect_error.h"
#include "support/grib_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using strielad::testing::expect_error;
using strielad::testing::ncarg_file;

struct Decoded {
  GribGridKeys keys;
  std::vector<double> latitudes, longitudes;  // ecCodes', one per sample in scanning order
};

Decoded decode(const std::filesystem::path& path, std::size_t message = 0) {
  const auto messages = list_grib_messages(path);
  std::lock_guard lock(eccodes_mutex());
  const GribHandle h = read_grib_message(path, messages.at(message));
  Decoded d;
  d.keys = read_grib_grid_keys(h, path.string());
  d.latitudes = h.double_array_key("latitudes", path.string());
  d.longitudes = h.double_array_key("longitudes", path.string());
  return d;
}

double longitude_gap(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return std::min(d, 360.0 - d);
}

// Every sample of the grid placed by its axes (and mapping) against ecCodes' position.
void expect_every_sample_placed(const std::filesystem::path& path, double tolerance_deg) {
  const Decoded d = decode(path);
  const GribGrid g = grib_grid(d.keys, path.string());
  // A global longitude axis repeats its first meridian at the end (periodic): the
  // message's samples are the first source_nx of each row.
  const std::size_t nx = g.placement.source_nx;
  ASSERT_EQ(nx * g.y.size(), d.latitudes.size()) << path;
  const std::string pipeline = g.placement.mapping ? g.placement.mapping->proj : "";
  const geo::GridProjection projection(pipeline);
  double worst = 0;
  for (std::size_t j = 0; j < g.y.size(); ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t n = j * nx + i;
      const auto [lon, lat] = projection.to_geographic(g.x.values[i], g.y.values[j]);
      worst =
          std::max({worst, std::abs(lat - d.latitudes[n]), longitude_gap(lon, d.longitudes[n])});
    }
  }
  EXPECT_LT(worst, tolerance_deg) << path << ": worst difference " << worst << " degrees";
}

TEST(GribGridTest, NcepLambertGridMatchesEcCodesAtEverySample) {
  const auto path = ncarg_file("grb/fh.0012_tl.press_gr.awp211.grb2");
  const GribGrid g = grib_grid(decode(path).keys, path.string());
  EXPECT_EQ(g.x.kind, AxisKind::kProjectionX);
  EXPECT_EQ(g.x.size(), 93u);
  EXPECT_EQ(g.y.size(), 65u);
  ASSERT_TRUE(g.placement.mapping);
  EXPECT_EQ(g.placement.mapping->name, "lambert_conformal_conic");
  EXPECT_NE(g.placement.mapping->proj.find("+R=6371229"), std::string::npos)
      << g.placement.mapping->proj;
  expect_every_sample_placed(path, 1e-4);
}

TEST(GribGridTest, CosmoRotatedGridMatchesEcCodesAtEverySample) {
  const auto path = ncarg_file("grb/MET9_IR108_cosmode_0909210000.grb2");
  const GribGrid g = grib_grid(decode(path).keys, path.string());
  EXPECT_EQ(g.x.kind, AxisKind::kProjectionX);
  EXPECT_TRUE(g.y.descending());  // jScansPositively 0: north to south, kept as stored
  ASSERT_TRUE(g.placement.mapping);
  EXPECT_EQ(g.placement.mapping->attributes["grid_north_pole_latitude"], 40.0);
  EXPECT_EQ(g.placement.mapping->attributes["grid_north_pole_longitude"], -170.0);
  // Its increments (0.024994 degrees both ways) miss its last points by 0.0033 degrees
  // (longitude) and 0.0013 (latitude): said in notes. The samples are placed evenly from
  // the first point to the last, as ecCodes places longitudes; ecCodes steps latitudes by
  // the increment and snaps the last, so inside the grid the two differ by up to 0.0013
  // degrees (5 % of a cell) in latitude.
  const auto said = [&](std::string_view text) {
    return std::any_of(
        g.placement.notes.begin(), g.placement.notes.end(),
        [&](const std::string& note) { return note.find(text) != std::string::npos; });
  };
  EXPECT_TRUE(said("longitude axis: 421 points"));
  EXPECT_TRUE(said("latitude axis: 461 points"));
  expect_every_sample_placed(path, 0.0013);
}

class GribTemplateTest : public ::testing::TestWithParam<const char*> {};

TEST_P(GribTemplateTest, MatchesEcCodesAtEverySample) {
  expect_every_sample_placed(std::filesystem::path("/usr/share/eccodes/samples") / GetParam(),
                             1e-4);
}

INSTANTIATE_TEST_SUITE_P(EcCodesSamples, GribTemplateTest,
                         ::testing::Values("regular_ll_pl_grib2.tmpl", "regular_ll_pl_grib1.tmpl",
                                           "regular_gg_pl_grib2.tmpl", "regular_gg_pl_grib1.tmpl",
                                           "rotated_ll_pl_grib2.tmpl", "rotated_ll_pl_grib1.tmpl"));

// NCEP-like polar stereographic grids, north and south, and a Mercator grid, written
// from ecCodes' templates with real-looking keys (no libncarg-data file has them). The
// polar grids scan +i, +j as NCEP's do: ecCodes 2.28 ignores the scanning flags of polar
// stereographic grids (it places -j scanning as +j), where this code follows the GRIB
// specification as for every other grid type.
TEST(GribGridTest, PolarStereographicGridsMatchEcCodesAtEverySample) {
  const testing::TempDir dir;
  for (const bool south : {false, true}) {
    const auto path = dir / (south ? "south.grb2" : "north.grb2");
    testing::write_grib_file(path, {{"polar_stereographic_pl_grib2",
                                     {{"Nx", 25L},
                                      {"Ny", 20L},
                                      {"latitudeOfFirstGridPointInDegrees", south ? -20.0 : 20.0},
                                      {"longitudeOfFirstGridPointInDegrees", 230.0},
                                      {"LaDInDegrees", south ? -60.0 : 60.0},
                                      {"orientationOfTheGridInDegrees", 255.0},
                                      {"DxInMetres", 190500.0},
                                      {"DyInMetres", 190500.0},
                                      {"projectionCentreFlag", south ? 128L : 0L},
                                      {"shapeOfTheEarth", 6L},
                                      {"jScansPositively", 1L}},
                                     std::vector<double>(500, 1.0)}});
    const GribGrid g = grib_grid(decode(path).keys, path.string());
    ASSERT_TRUE(g.placement.mapping);
    EXPECT_EQ(g.placement.mapping->name, "polar_stereographic");
    expect_every_sample_placed(path, 1e-4);
  }
}

TEST(GribGridTest, MercatorGridMatchesEcCodesAtEverySample) {
  const testing::TempDir dir;
  const auto path = dir / "mercator.grb2";
  testing::write_grib_file(path, {{"regular_ll_pl_grib2",
                                   {{"gridDefinitionTemplateNumber", 10L},
                                    {"Ni", 30L},
                                    {"Nj", 24L},
                                    {"latitudeOfFirstGridPointInDegrees", -10.0},
                                    {"longitudeOfFirstGridPointInDegrees", 120.0},
                                    {"LaDInDegrees", 20.0},
                                    {"orientationOfTheGridInDegrees", 0.0},
                                    {"DiInMetres", 50000.0},
                                    {"DjInMetres", 50000.0},
                                    {"iScansNegatively", 0L},
                                    {"jScansPositively", 1L},
                                    {"shapeOfTheEarth", 6L}},
                                   std::vector<double>(720, 1.0)}});
  const Decoded d = decode(path);
  ASSERT_EQ(d.keys.grid_type, "mercator");
  const GribGrid g = grib_grid(d.keys, path.string());
  ASSERT_TRUE(g.placement.mapping);
  EXPECT_EQ(g.placement.mapping->name, "mercator");
  expect_every_sample_placed(path, 1e-4);
}

TEST(GribGridTest, GlobalRegularGridIsPeriodic) {
  const auto path = std::filesystem::path("/usr/share/eccodes/samples/regular_gg_pl_grib2.tmpl");
  const GribGrid g = grib_grid(decode(path).keys, path.string());
  EXPECT_EQ(g.x.kind, AxisKind::kLongitude);
  EXPECT_EQ(g.y.kind, AxisKind::kLatitude);
  EXPECT_TRUE(g.x.periodic);
  EXPECT_FALSE(g.placement.mapping);
}

TEST(GribGridTest, ReducedGridIsRefusedWithHowToRegridIt) {
  const auto path = ncarg_file("grb/wafsgfs_L_t06z_intdsk60.grib2");
  const GribGridKeys keys = decode(path).keys;
  expect_error([&] { grib_grid(keys, "wafsgfs"); }, ErrorCode::kUnsupported,
               {"wafsgfs", "reduced_ll", "rows of different lengths", "cdo setgridtype,regular"});
}

GribGridKeys lambert_keys() {
  return decode(ncarg_file("grb/fh.0012_tl.press_gr.awp211.grb2")).keys;
}

TEST(GribGridTest, ScanningThisCodeDoesNotReadIsRefused) {
  GribGridKeys k = lambert_keys();
  k.alternative_row_scanning = true;
  expect_error([&] { grib_grid(k, "m1"); }, ErrorCode::kUnsupported,
               {"m1", "alternativeRowScanning"});
  k = lambert_keys();
  k.j_points_are_consecutive = true;
  expect_error([&] { grib_grid(k, "m1"); }, ErrorCode::kUnsupported,
               {"m1", "jPointsAreConsecutive"});
}

TEST(GribGridTest, KeysOutOfRangeAreNamed) {
  GribGridKeys k = lambert_keys();
  k.dx_metres = GribGridKeys::kAbsent;
  expect_error([&] { grib_grid(k, "m2"); }, ErrorCode::kInvalidInput,
               {"m2", "DxInMetres", "missing"});
  k = lambert_keys();
  k.shape_of_the_earth = 9;
  expect_error([&] { grib_grid(k, "m2"); }, ErrorCode::kUnsupported, {"m2", "shapeOfTheEarth 9"});
  k = lambert_keys();
  k.projection_centre = 64;
  expect_error([&] { grib_grid(k, "m2"); }, ErrorCode::kUnsupported, {"m2", "bipolar"});
  k = lambert_keys();
  k.grid_type = "space_view";
  expect_error([&] { grib_grid(k, "m2"); }, ErrorCode::kUnsupported,
               {"m2", "space_view", "regular_ll"});
}

TEST(GribGridTest, RotatedGridWithARotationAngleIsRefused) {
  GribGridKeys k = decode(ncarg_file("grb/MET9_IR108_cosmode_0909210000.grb2")).keys;
  k.rotation_angle = 15;
  expect_error([&] { grib_grid(k, "m3"); }, ErrorCode::kUnsupported,
               {"m3", "angleOfRotationInDegrees = 15"});
}

TEST(GribGridTest, LatitudesAgainstTheScanningFlagAreRefused) {
  GribGridKeys k = decode(ncarg_file("grb/MET9_IR108_cosmode_0909210000.grb2")).keys;
  k.j_scans_positively = true;  // but the latitudes run north to south
  expect_error([&] { grib_grid(k, "m4"); }, ErrorCode::kInvalidInput,
               {"m4", "jScansPositively is 1"});
}

}  // namespace
}  // namespace strielad::ingest
