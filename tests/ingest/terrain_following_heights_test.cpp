// SPDX-License-Identifier: Apache-2.0
// Explicit height fields placing terrain-following levels: ICON z_mc (full levels) and
// z_ifc (half levels), COSMO HHL, a --height-var geopotential; the surface height; and
// the refusals: two candidates, wrong shape or units, missing values, columns that are
// not strictly monotonic or run the other way.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "support/expect_error.h"
#include "support/model_levels_fixture.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using strielad::testing::expect_error;
using strielad::testing::field;
using strielad::testing::ModelLevels;
using strielad::testing::NcAttr;
using strielad::testing::TempDir;

const NcAttr kMetres = NcAttr::text_value("units", "m");

// Half-level heights, falling with k (ICON counts from the top), distinct per column and
// step, squared so that the means are not the half levels' own spacing.
double half_level_height(std::size_t t, std::size_t k, std::size_t s) {
  const double top = 4.0 - static_cast<double>(k);
  return 1000.0 * top * top + 10.0 * static_cast<double>(s) + 3.0 * static_cast<double>(t);
}

// Scan options converting T alone (the height and term variables are 3-D fields too).
ScanOptions only_t() {
  ScanOptions o;
  o.variables = {"T"};
  return o;
}

std::vector<double> read_geometry(const InputCatalog& c, std::size_t step, std::size_t z0,
                                  std::size_t z1) {
  SlabReader reader(c, {});
  std::vector<double> out((z1 - z0) * c.y.size() * c.x.size());
  reader.read_vertical_geometry(step, z0, z1, out);
  return out;
}

TEST(TerrainFollowingHeightsTest, HalfLevelHeightsAreMeansOfTheTwoAroundEachLevel) {
  TempDir dir;
  const ModelLevels g;
  g.fixture()
      .dimension("height_2", g.nz + 1)
      .variable("z_ifc", NC_DOUBLE, {"height_2", "lat", "lon"},
                field(1, g.nz + 1, g.plane(),
                      [](std::size_t, std::size_t k, std::size_t s) {
                        return half_level_height(0, k, s);
                      }),
                {kMetres})
      .write(dir / "icon.nc");
  const InputCatalog c = scan_inputs({dir / "icon.nc"}, {});
  ASSERT_TRUE(c.vertical_geometry);
  EXPECT_EQ(c.vertical_geometry->formula, "variable");
  EXPECT_EQ(c.vertical_geometry->quantity, VerticalGeometrySource::Quantity::kHeight);
  EXPECT_EQ(c.vertical_geometry->sources, std::vector<std::string>{"z_ifc"});
  EXPECT_FALSE(c.vertical_geometry->varies_in_time);
  for (std::size_t step : {0u, 1u}) {
    const auto got = read_geometry(c, step, 1, 3);  // levels 1 and 2
    for (std::size_t k = 1; k < 3; ++k) {
      for (std::size_t s = 0; s < g.plane(); ++s) {
        const double want = 0.5 * (half_level_height(0, k, s) + half_level_height(0, k + 1, s));
        ASSERT_EQ(got[(k - 1) * g.plane() + s], want) << "k " << k << " s " << s;
      }
    }
  }
}

TEST(TerrainFollowingHeightsTest, FullLevelHeightsAreReadAsStored) {
  TempDir dir;
  const ModelLevels g;
  auto z = [](std::size_t, std::size_t k, std::size_t s) { return half_level_height(0, k, s); };
  g.fixture()
      .variable("z_mc", NC_FLOAT, {"lev", "lat", "lon"}, field(1, g.nz, g.plane(), z), {kMetres})
      .write(dir / "icon.nc");
  const InputCatalog c = scan_inputs({dir / "icon.nc"}, only_t());
  ASSERT_TRUE(c.vertical_geometry);
  EXPECT_EQ(c.vertical_geometry->sources, std::vector<std::string>{"z_mc"});
  const auto got = read_geometry(c, 0, 0, g.nz);
  EXPECT_EQ(got, field(1, g.nz, g.plane(), z));
}

TEST(TerrainFollowingHeightsTest, CosmoHhlVaryingInTimeIsAveragedPerStep) {
  TempDir dir;
  const ModelLevels g;
  g.fixture()
      .dimension("level1", g.nz + 1)
      .variable("HHL", NC_FLOAT, {"time", "level1", "lat", "lon"},
                field(g.nt, g.nz + 1, g.plane(), half_level_height), {kMetres})
      .write(dir / "cosmo.nc");
  const InputCatalog c = scan_inputs({dir / "cosmo.nc"}, only_t());
  ASSERT_TRUE(c.vertical_geometry);
  EXPECT_EQ(c.vertical_geometry->sources, std::vector<std::string>{"HHL"});
  EXPECT_TRUE(c.vertical_geometry->varies_in_time);
  for (std::size_t t = 0; t < g.nt; ++t) {
    const auto got = read_geometry(c, t, 0, g.nz);
    for (std::size_t k = 0; k < g.nz; ++k) {
      for (std::size_t s = 0; s < g.plane(); ++s) {
        ASSERT_EQ(got[k * g.plane() + s],
                  0.5 * (half_level_height(t, k, s) + half_level_height(t, k + 1, s)))
            << "t " << t << " k " << k << " s " << s;
      }
    }
  }
}

TEST(TerrainFollowingHeightsTest, HeightVarGeopotentialIsDividedByStandardGravity) {
  TempDir dir;
  const ModelLevels g;
  auto phi = [](std::size_t t, std::size_t k, std::size_t s) {
    return 9.80665 * half_level_height(t, k, s);
  };
  g.fixture()
      .variable("PHI", NC_DOUBLE, {"time", "lev", "lat", "lon"}, field(g.nt, g.nz, g.plane(), phi),
                {NcAttr::text_value("units", "m2 s-2")})
      .write(dir / "phi.nc");
  ScanOptions o;
  o.variables = {"T"};
  o.height_var = "PHI";
  const InputCatalog c = scan_inputs({dir / "phi.nc"}, o);
  ASSERT_TRUE(c.vertical_geometry);
  EXPECT_EQ(c.vertical_geometry->sources, std::vector<std::string>{"PHI"});
  const auto got = read_geometry(c, 1, 0, g.nz);
  for (std::size_t k = 0; k < g.nz; ++k) {
    for (std::size_t s = 0; s < g.plane(); ++s) {
      ASSERT_DOUBLE_EQ(got[k * g.plane() + s], half_level_height(1, k, s));
    }
  }
}

TEST(TerrainFollowingHeightsTest, HeightVarChoosesAmongAutomaticCandidates) {
  TempDir dir;
  const ModelLevels g;
  auto z = [](std::size_t, std::size_t k, std::size_t s) { return half_level_height(0, k, s); };
  g.fixture()
      .dimension("height_2", g.nz + 1)
      .variable("z_mc", NC_DOUBLE, {"lev", "lat", "lon"}, field(1, g.nz, g.plane(), z), {kMetres})
      .variable("HHL", NC_DOUBLE, {"height_2", "lat", "lon"}, field(1, g.nz + 1, g.plane(), z),
                {kMetres})
      .write(dir / "two.nc");
  expect_error([&] { scan_inputs({dir / "two.nc"}, only_t()); }, ErrorCode::kInvalidInput,
               {"'z_mc'", "'HHL'", "--height-var", "two.nc"});
  ScanOptions o;
  o.variables = {"T"};
  o.height_var = "HHL";
  const InputCatalog c = scan_inputs({dir / "two.nc"}, o);
  ASSERT_TRUE(c.vertical_geometry);
  EXPECT_EQ(c.vertical_geometry->sources, std::vector<std::string>{"HHL"});
}

TEST(TerrainFollowingHeightsTest, IconsZmcIsPreferredToItsZifc) {
  TempDir dir;
  const ModelLevels g;
  auto z = [](std::size_t, std::size_t k, std::size_t s) { return half_level_height(0, k, s); };
  g.fixture()
      .dimension("height_2", g.nz + 1)
      .variable("z_mc", NC_DOUBLE, {"lev", "lat", "lon"}, field(1, g.nz, g.plane(), z), {kMetres})
      .variable("z_ifc", NC_DOUBLE, {"height_2", "lat", "lon"}, field(1, g.nz + 1, g.plane(), z),
                {kMetres})
      .write(dir / "icon.nc");
  const InputCatalog c = scan_inputs({dir / "icon.nc"}, {});
  ASSERT_TRUE(c.vertical_geometry);
  EXPECT_EQ(c.vertical_geometry->sources, std::vector<std::string>{"z_mc"});
  // The height fields place the grid: by default they are not converted as data.
  ASSERT_EQ(c.variables.size(), 1u);
  EXPECT_EQ(c.variables[0].name, "T");
}

TEST(TerrainFollowingHeightsTest, HeightVarMissingFromTheInputsIsNotFound) {
  TempDir dir;
  ModelLevels{}.fixture().write(dir / "t.nc");
  ScanOptions o;
  o.height_var = "ZG";
  expect_error([&] { scan_inputs({dir / "t.nc"}, o); }, ErrorCode::kNotFound,
               {"'ZG'", "--height-var"});
}

TEST(TerrainFollowingHeightsTest, HeightOnOtherLevelsIsRefused) {
  TempDir dir;
  const ModelLevels g;
  g.fixture()
      .dimension("height_3", g.nz + 2)
      .variable("z_ifc", NC_DOUBLE, {"height_3", "lat", "lon"},
                std::vector<double>((g.nz + 2) * g.plane(), 1.0), {kMetres})
      .write(dir / "icon.nc");
  expect_error([&] { scan_inputs({dir / "icon.nc"}, only_t()); }, ErrorCode::kInvalidInput,
               {"icon.nc", "'z_ifc'", "(height_3, lat, lon)", "(5, 3, 4)"});
}

TEST(TerrainFollowingHeightsTest, HeightWithoutHeightUnitsIsRefused) {
  TempDir dir;
  const ModelLevels g;
  g.fixture()
      .variable("z_mc", NC_DOUBLE, {"lev", "lat", "lon"},
                std::vector<double>(g.nz * g.plane(), 1.0), {NcAttr::text_value("units", "K")})
      .write(dir / "icon.nc");
  expect_error([&] { scan_inputs({dir / "icon.nc"}, only_t()); }, ErrorCode::kInvalidInput,
               {"icon.nc", "'z_mc'", "units 'K'"});
}

TEST(TerrainFollowingHeightsTest, FillValueInHeightsNamesFileVariableSampleAndStep) {
  TempDir dir;
  const ModelLevels g;
  auto z = field(g.nt, g.nz, g.plane(), half_level_height);
  z[(1 * g.nz + 2) * g.plane() + 1 * g.nx + 3] = -999.0;  // t 1, k 2, j 1, i 3
  g.fixture()
      .variable("z_mc", NC_DOUBLE, {"time", "lev", "lat", "lon"}, z,
                {kMetres, NcAttr::number("_FillValue", NC_DOUBLE, {-999.0})})
      .write(dir / "icon.nc");
  const InputCatalog c = scan_inputs({dir / "icon.nc"}, only_t());
  EXPECT_NO_THROW(read_geometry(c, 0, 0, g.nz));
  EXPECT_NO_THROW(read_geometry(c, 1, 0, 2));
  expect_error([&] { read_geometry(c, 1, 0, g.nz); }, ErrorCode::kInvalidInput,
               {"icon.nc", "'z_mc'", "time step 1", "(i 3, j 1, k 2)"});
}

TEST(TerrainFollowingHeightsTest, ColumnWithARepeatedHeightNamesTheSample) {
  TempDir dir;
  const ModelLevels g;
  auto z = field(1, g.nz, g.plane(), half_level_height);
  z[2 * g.plane() + 2 * g.nx + 1] = z[1 * g.plane() + 2 * g.nx + 1];  // k 2 = k 1 at (1, 2)
  g.fixture()
      .variable("z_mc", NC_DOUBLE, {"lev", "lat", "lon"}, z, {kMetres})
      .write(dir / "icon.nc");
  const InputCatalog c = scan_inputs({dir / "icon.nc"}, only_t());
  expect_error([&] { read_geometry(c, 1, 0, g.nz); }, ErrorCode::kInvalidInput,
               {"icon.nc", "z_mc", "time step 1", "(i 1, j 2, k 2)", "not strictly monotonic"});
}

TEST(TerrainFollowingHeightsTest, ColumnRunningTheOtherWayNamesTheSample) {
  TempDir dir;
  const ModelLevels g;
  auto z = field(1, g.nz, g.plane(), half_level_height);
  for (std::size_t k = 0; k < g.nz; ++k) z[k * g.plane() + 5] = 100.0 * static_cast<double>(k);
  g.fixture()
      .variable("z_mc", NC_DOUBLE, {"lev", "lat", "lon"}, z, {kMetres})
      .write(dir / "icon.nc");
  const InputCatalog c = scan_inputs({dir / "icon.nc"}, only_t());
  expect_error([&] { read_geometry(c, 0, 0, g.nz); }, ErrorCode::kInvalidInput,
               {"icon.nc", "z_mc", "time step 0", "(i 1, j 1, k 1)", "other way"});
}

TEST(TerrainFollowingHeightsTest, TimeInvariantHeightsMayLieInAnotherFile) {
  TempDir dir;
  const ModelLevels g;
  g.fixture().write(dir / "data.nc");
  auto z = [](std::size_t, std::size_t k, std::size_t s) { return half_level_height(0, k, s); };
  testing::NetcdfFixture()
      .dimension("height_2", g.nz + 1)
      .dimension("lat", g.ny)
      .dimension("lon", g.nx)
      .variable("z_ifc", NC_DOUBLE, {"height_2", "lat", "lon"}, field(1, g.nz + 1, g.plane(), z),
                {kMetres})
      .write(dir / "constants.nc");
  const InputCatalog c = scan_inputs({dir / "data.nc", dir / "constants.nc"}, {});
  ASSERT_TRUE(c.vertical_geometry);
  const auto got = read_geometry(c, 1, 0, 1);
  EXPECT_EQ(got[7], 0.5 * (z(0, 0, 7) + z(0, 1, 7)));
}

TEST(TerrainFollowingHeightsTest, PeriodicLongitudeRepeatsTheFirstColumn) {
  TempDir dir;
  ModelLevels g;
  g.lon = {0.0, 90.0, 180.0, 270.0};  // round the Earth: the catalog repeats lon 0 at 360
  auto z = [](std::size_t, std::size_t k, std::size_t s) { return half_level_height(0, k, s); };
  g.fixture()
      .variable("z_mc", NC_DOUBLE, {"lev", "lat", "lon"}, field(1, g.nz, g.plane(), z), {kMetres})
      .write(dir / "global.nc");
  const InputCatalog c = scan_inputs({dir / "global.nc"}, only_t());
  ASSERT_EQ(c.x.size(), 5u);
  const auto got = read_geometry(c, 0, 2, 3);
  for (std::size_t j = 0; j < g.ny; ++j) {
    for (std::size_t i = 0; i <= g.nx; ++i) {
      ASSERT_EQ(got[j * 5 + i], z(0, 2, j * g.nx + i % g.nx)) << i << ", " << j;
    }
  }
}

TEST(TerrainFollowingHeightsTest, SurfaceHeightIsDetectedAndReadInMetres) {
  TempDir dir;
  const ModelLevels g;
  g.fixture()
      .variable("HSURF", NC_FLOAT, {"lat", "lon"}, testing::ramp(g.plane(), 100.0, 25.0), {kMetres})
      .write(dir / "cosmo.nc");
  const InputCatalog c = scan_inputs({dir / "cosmo.nc"}, only_t());
  ASSERT_TRUE(c.surface);
  EXPECT_EQ(c.surface->variable, "HSURF");
  EXPECT_FALSE(c.vertical_geometry);
  SlabReader reader(c, {});
  std::vector<double> out(g.plane());
  reader.read_surface(out);
  EXPECT_EQ(out, testing::ramp(g.plane(), 100.0, 25.0));
  std::vector<double> level(g.plane());
  expect_error([&] { reader.read_vertical_geometry(0, 0, 1, level); }, ErrorCode::kInvalidArgument,
               {"no vertical geometry"});
}

TEST(TerrainFollowingHeightsTest, SurfaceOverTimeInKilometresTakesTheFirstStep) {
  TempDir dir;
  const ModelLevels g;
  std::vector<double> topo = testing::ramp(g.plane(), 0.5, 0.25);
  std::vector<double> both = topo;
  both.insert(both.end(), topo.begin(), topo.end());
  g.fixture()
      .variable("topography_c", NC_DOUBLE, {"time", "lat", "lon"}, both,
                {NcAttr::text_value("units", "km")})
      .write(dir / "icon.nc");
  const InputCatalog c = scan_inputs({dir / "icon.nc"}, only_t());
  ASSERT_TRUE(c.surface);
  EXPECT_EQ(c.surface->variable, "topography_c");
  SlabReader reader(c, {});
  std::vector<double> out(g.plane());
  reader.read_surface(out);
  for (std::size_t s = 0; s < g.plane(); ++s) EXPECT_EQ(out[s], topo[s] * 1000.0);
}

TEST(TerrainFollowingHeightsTest, SurfaceCandidateThatIsNoHeightIsIgnored) {
  TempDir dir;
  const ModelLevels g;
  g.fixture()
      .variable("HGT", NC_FLOAT, {"lat", "lon"}, testing::ramp(g.plane()),
                {NcAttr::text_value("units", "K")})
      .write(dir / "t.nc");
  const InputCatalog c = scan_inputs({dir / "t.nc"}, only_t());
  EXPECT_FALSE(c.surface);
}

}  // namespace
}  // namespace strielad::ingest
