// SPDX-License-Identifier: Apache-2.0
// GRIB and netCDF inputs of one conversion (NCEP's AWIPS 211 forecast from libncarg-data,
// one variable written as CF-NetCDF on its grid): joined into one catalog when they agree
// exactly, each variable read from its own file; refused, naming a file of each side and
// what differs, when the grids, projections or times differ or a variable is on both.
#include <gtest/gtest.h>

#include <filesystem>

#include "ingest/input_catalog.h"
#include "support/expect_error.h"
#include "support/grib_as_netcdf.h"
#include "support/model_levels_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using strielad::testing::expect_error;
using strielad::testing::GribAsNetcdf;
using strielad::testing::ncarg_file;

std::filesystem::path forecast() { return ncarg_file("grb/fh.0012_tl.press_gr.awp211.grb2"); }

// The forecast's relative humidity alone, as GRIB.
std::filesystem::path humidity_grib(const testing::TempDir& dir) {
  const auto path = dir / "r.grb2";
  testing::copy_grib_variable(forecast(), "r", path);
  return path;
}

std::filesystem::path netcdf_copy(const testing::TempDir& dir, const GribAsNetcdf& spec) {
  const auto path = dir / (spec.name + ".nc");
  testing::write_grib_variable_as_netcdf(forecast(), spec, path);
  return path;
}

TEST(GribNetcdfMixTest, GribAndNetcdfVariablesOnOneGridJoinInOneCatalog) {
  const testing::TempDir dir;
  const auto grib = humidity_grib(dir);
  const auto nc = netcdf_copy(dir, {});
  const InputCatalog c = scan_inputs({grib, nc}, {});
  ASSERT_EQ(c.variables.size(), 2u);
  EXPECT_EQ(c.variables[0].name, "r");
  EXPECT_EQ(c.variables[1].name, "t");
  EXPECT_EQ(c.files.size(), 2u);
  EXPECT_EQ(c.dims(), (Dims3{93, 65, 19}));
  ASSERT_TRUE(c.grid_mapping);
  EXPECT_EQ(c.grid_mapping->name, "lambert_conformal_conic");
  // The GRIB side comes first: its units; the netCDF hours are the same instant.
  EXPECT_EQ(c.time.units, "seconds since 1970-01-01 00:00:00");
  EXPECT_EQ(c.time.calendar, "proleptic_gregorian");
  ASSERT_EQ(c.time.values.size(), 1u);
  EXPECT_EQ(c.time.values[0], 1169640000.0);
  ASSERT_EQ(c.locations.size(), 2u);
  EXPECT_EQ(c.locations[0][0].file, 0u);
  EXPECT_EQ(c.locations[0][0].grib_levels.size(), 19u);
  EXPECT_EQ(c.locations[1][0].file, 1u);
  EXPECT_TRUE(c.locations[1][0].grib_levels.empty());
}

TEST(GribNetcdfMixTest, NetcdfFirstGivesItsTimeUnits) {
  const testing::TempDir dir;
  const auto grib = humidity_grib(dir);
  const auto nc = netcdf_copy(dir, {});
  const InputCatalog c = scan_inputs({nc, grib}, {});
  ASSERT_EQ(c.variables.size(), 2u);
  EXPECT_EQ(c.variables[0].name, "t");
  EXPECT_EQ(c.variables[1].name, "r");
  EXPECT_EQ(c.time.units, "hours since 1970-01-01 00:00:00");
  ASSERT_EQ(c.time.values.size(), 1u);
  EXPECT_EQ(c.time.values[0], 324900.0);
  EXPECT_EQ(c.files[c.locations[1][0].file].path, std::filesystem::absolute(grib).string());
}

TEST(GribNetcdfMixTest, VariablesAskedForAreTakenFromEitherFormat) {
  const testing::TempDir dir;
  GribAsNetcdf spec;
  spec.name = "tmp";
  const auto nc = netcdf_copy(dir, spec);
  ScanOptions o;
  o.variables = {"tmp", "/gh"};  // a leading slash as for netCDF alone
  const InputCatalog c = scan_inputs({forecast(), nc}, o);
  ASSERT_EQ(c.variables.size(), 2u);
  EXPECT_EQ(c.variables[0].name, "tmp");  // in the order asked for
  EXPECT_EQ(c.variables[1].name, "gh");
  EXPECT_EQ(c.files[c.locations[1][0].file].path, forecast().string());
}

TEST(GribNetcdfMixTest, AVariableAskedForThatNeitherFormatHasIsNamed) {
  const testing::TempDir dir;
  const auto nc = netcdf_copy(dir, {});
  ScanOptions o;
  o.variables = {"t", "q"};
  expect_error([&] { scan_inputs({humidity_grib(dir), nc}, o); }, ErrorCode::kNotFound,
               {"variable 'q' is in no input", "r.grb2", "t.nc"});
}

TEST(GribNetcdfMixTest, AVariableInBothFormatsIsRefused) {
  const testing::TempDir dir;
  const auto nc = netcdf_copy(dir, {});
  // By default the forecast's six isobaric variables are taken, t among them.
  expect_error([&] { scan_inputs({forecast(), nc}, {}); }, ErrorCode::kInvalidInput,
               {"variable 't'", "fh.0012_tl.press_gr.awp211.grb2", "t.nc", "one format"});
  ScanOptions o;
  o.variables = {"t"};
  expect_error([&] { scan_inputs({forecast(), nc}, o); }, ErrorCode::kInvalidInput,
               {"variable 't'", "fh.0012_tl.press_gr.awp211.grb2", "t.nc", "one format"});
}

TEST(GribNetcdfMixTest, NetcdfWithFewerColumnsIsRefused) {
  const testing::TempDir dir;
  GribAsNetcdf spec;
  spec.drop_columns = 1;
  const auto nc = netcdf_copy(dir, spec);
  expect_error([&] { scan_inputs({humidity_grib(dir), nc}, {}); }, ErrorCode::kInvalidInput,
               {"t.nc", "not on the grid", "r.grb2", "92 values", "93"});
}

TEST(GribNetcdfMixTest, AnotherProjectionIsRefused) {
  const testing::TempDir dir;
  GribAsNetcdf spec;
  spec.central_meridian_shift = 1;
  const auto nc = netcdf_copy(dir, spec);
  expect_error([&] { scan_inputs({humidity_grib(dir), nc}, {}); }, ErrorCode::kInvalidInput,
               {"t.nc", "grid mapping 'lcc'", "r.grb2", "grid mapping 'grib_grid'", "+lon_0"});
}

TEST(GribNetcdfMixTest, AnotherValidityTimeIsRefused) {
  const testing::TempDir dir;
  GribAsNetcdf spec;
  spec.hours_later = 6;
  const auto nc = netcdf_copy(dir, spec);
  expect_error([&] { scan_inputs({humidity_grib(dir), nc}, {}); }, ErrorCode::kInvalidInput,
               {"t.nc", "no time step 1169640000", "r.grb2", "same time steps"});
}

TEST(GribNetcdfMixTest, NetcdfWithoutTimeIsRefused) {
  const testing::TempDir dir;
  GribAsNetcdf spec;
  spec.with_time = false;
  const auto nc = netcdf_copy(dir, spec);
  expect_error([&] { scan_inputs({humidity_grib(dir), nc}, {}); }, ErrorCode::kInvalidInput,
               {"t.nc", "no time dimension", "r.grb2"});
}

TEST(GribNetcdfMixTest, TerrainFollowingNetcdfLevelsAreNotMixed) {
  const testing::TempDir dir;
  const testing::ModelLevels g;
  g.fixture()
      .variable("z_mc", NC_FLOAT, {"lev", "lat", "lon"},
                testing::field(1, g.nz, g.plane(),
                               [](std::size_t, std::size_t k, std::size_t) {
                                 return 1000.0 - 100.0 * static_cast<double>(k);
                               }),
                {testing::NcAttr::text_value("units", "m")})
      .write(dir / "icon.nc");
  expect_error([&] { scan_inputs({humidity_grib(dir), dir / "icon.nc"}, {}); },
               ErrorCode::kUnsupported,
               {"icon.nc", "netCDF variables", "vertical geometry", "z_mc", "r.grb2",
                "convert each format separately"});
}

TEST(GribNetcdfMixTest, StepRangeSelectsAmongTheJoinedSteps) {
  const testing::TempDir dir;
  const auto nc = netcdf_copy(dir, {});
  ScanOptions o;
  o.first_step = 1;
  expect_error([&] { scan_inputs({humidity_grib(dir), nc}, o); }, ErrorCode::kInvalidArgument,
               {"first time step 1", "1 time step"});
}

}  // namespace
}  // namespace strielad::ingest
