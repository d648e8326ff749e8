// SPDX-License-Identifier: Apache-2.0
// CF parametric vertical coordinates (formula_terms on the z coordinate): hybrid height
// (z = a + b * orog), hybrid sigma-pressure (p = a * p0 + b * ps, or ap + b * ps) and
// sigma (p = ptop + sigma * (ps - ptop)) evaluated exactly per step, and each refusal:
// a missing term or term variable, a term of the wrong shape, an unknown formula, a
// missing ps time step, missing values.
#include <gtest/gtest.h>

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
using strielad::testing::NetcdfFixture;
using strielad::testing::TempDir;
using Quantity = VerticalGeometrySource::Quantity;

ModelLevels levels(const std::string& standard_name, const std::string& formula_terms) {
  ModelLevels g;
  g.lev_attrs.push_back(NcAttr::text_value("standard_name", standard_name));
  g.lev_attrs.push_back(NcAttr::text_value("formula_terms", formula_terms));
  return g;
}

const std::vector<double> kA{20.0, 1500.25, 4000.5};
const std::vector<double> kB{0.875, 0.5, 0.0625};
double orog(std::size_t s) { return 100.0 + 37.5 * static_cast<double>(s); }
double ps(std::size_t t, std::size_t s) {
  return 98000.0 + 125.0 * static_cast<double>(s) - 500.0 * static_cast<double>(t);
}

// Scan options converting T alone (the height and term variables are 3-D fields too).
ScanOptions only_t() {
  ScanOptions o;
  o.variables = {"T"};
  return o;
}

std::vector<double> read_geometry(const InputCatalog& c, std::size_t step, std::size_t z0,
                                  std::size_t z1, const ScanOptions& o = {}) {
  SlabReader reader(c, o);
  std::vector<double> out((z1 - z0) * c.y.size() * c.x.size());
  reader.read_vertical_geometry(step, z0, z1, out);
  return out;
}

NetcdfFixture hybrid_height_file(const ModelLevels& g) {
  return g.fixture()
      .variable("a", NC_DOUBLE, {"lev"}, kA, {NcAttr::text_value("units", "m")})
      .variable("b", NC_DOUBLE, {"lev"}, kB, {NcAttr::text_value("units", "1")})
      .variable(
          "orog", NC_DOUBLE, {"lat", "lon"},
          field(1, 1, g.plane(), [](std::size_t, std::size_t, std::size_t s) { return orog(s); }),
          {NcAttr::text_value("units", "m")});
}

TEST(CfFormulaLevelsTest, HybridHeightIsAPlusBTimesOrography) {
  TempDir dir;
  const ModelLevels g = levels("atmosphere_hybrid_height_coordinate", "a: a b: b orog: orog");
  hybrid_height_file(g).write(dir / "um.nc");
  const InputCatalog c = scan_inputs({dir / "um.nc"}, only_t());
  EXPECT_EQ(c.z.kind, AxisKind::kModelLevel);
  ASSERT_TRUE(c.vertical_geometry);
  const VerticalGeometrySource& v = *c.vertical_geometry;
  EXPECT_EQ(v.quantity, Quantity::kHeight);
  EXPECT_EQ(v.formula, "atmosphere_hybrid_height_coordinate");
  EXPECT_EQ(v.terms,
            (std::map<std::string, std::string>{{"a", "a"}, {"b", "b"}, {"orog", "orog"}}));
  EXPECT_FALSE(v.varies_in_time);
  ASSERT_TRUE(c.surface);
  EXPECT_EQ(c.surface->variable, "orog");
  const auto got = read_geometry(c, 1, 0, g.nz);
  for (std::size_t k = 0; k < g.nz; ++k) {
    for (std::size_t s = 0; s < g.plane(); ++s) {
      ASSERT_EQ(got[k * g.plane() + s], kA[k] + kB[k] * orog(s)) << "k " << k << " s " << s;
    }
  }
}

TEST(CfFormulaLevelsTest, AxisWithFormulaTermsIsNeverTakenAsHeights) {
  TempDir dir;
  ModelLevels g = levels("atmosphere_hybrid_height_coordinate", "a: a b: b orog: orog");
  g.lev_attrs.push_back(NcAttr::text_value("units", "m"));
  hybrid_height_file(g).write(dir / "um.nc");
  EXPECT_EQ(scan_inputs({dir / "um.nc"}, only_t()).z.kind, AxisKind::kModelLevel);
  // standard_name "height" with formula_terms: no formula it names, so refused.
  ModelLevels h = levels("height", "a: a b: b orog: orog");
  h.lev_attrs.push_back(NcAttr::text_value("units", "m"));
  hybrid_height_file(h).write(dir / "um_height.nc");
  expect_error([&] { scan_inputs({dir / "um_height.nc"}, only_t()); }, ErrorCode::kUnsupported,
               {"'height'", "atmosphere_hybrid_height_coordinate"});
}

NetcdfFixture sigma_pressure_file(const ModelLevels& g, const std::string& ps_units = "Pa") {
  const double scale = ps_units == "hPa" ? 0.01 : 1.0;
  return g.fixture()
      .variable("hyam", NC_DOUBLE, {"lev"}, {0.0125, 0.25, 0.5})
      .variable("hybm", NC_DOUBLE, {"lev"}, kB)
      .variable("P0", NC_DOUBLE, {}, {100000.0}, {NcAttr::text_value("units", "Pa")})
      .variable("PS", NC_DOUBLE, {"time", "lat", "lon"},
                field(g.nt, 1, g.plane(),
                      [&](std::size_t t, std::size_t, std::size_t s) { return ps(t, s) * scale; }),
                {NcAttr::text_value("units", ps_units)});
}

TEST(CfFormulaLevelsTest, HybridSigmaPressureFollowsSurfacePressureOfEachStep) {
  TempDir dir;
  const ModelLevels g =
      levels("atmosphere_hybrid_sigma_pressure_coordinate", "a: hyam b: hybm p0: P0 ps: PS");
  sigma_pressure_file(g).write(dir / "cam.nc");
  const InputCatalog c = scan_inputs({dir / "cam.nc"}, only_t());
  ASSERT_TRUE(c.vertical_geometry);
  const VerticalGeometrySource& v = *c.vertical_geometry;
  EXPECT_EQ(v.quantity, Quantity::kPressure);
  EXPECT_TRUE(v.varies_in_time);
  EXPECT_EQ(v.terms.at("ps"), "PS");
  const std::vector<double> a{0.0125, 0.25, 0.5};
  for (std::size_t t = 0; t < g.nt; ++t) {
    const auto got = read_geometry(c, t, 0, g.nz);
    for (std::size_t k = 0; k < g.nz; ++k) {
      for (std::size_t s = 0; s < g.plane(); ++s) {
        ASSERT_EQ(got[k * g.plane() + s], a[k] * 100000.0 + kB[k] * ps(t, s))
            << "t " << t << " k " << k << " s " << s;
      }
    }
  }
}

TEST(CfFormulaLevelsTest, HybridSigmaPressureWithApAndPsInHectopascals) {
  TempDir dir;
  const ModelLevels g =
      levels("atmosphere_hybrid_sigma_pressure_coordinate", "ap: ap b: hybm ps: PS");
  sigma_pressure_file(g, "hPa")
      .variable("ap", NC_DOUBLE, {"lev"}, {12.5, 250.0, 500.0},
                {NcAttr::text_value("units", "hPa")})
      .write(dir / "cmip.nc");
  const InputCatalog c = scan_inputs({dir / "cmip.nc"}, only_t());
  const auto got = read_geometry(c, 1, 1, 3);
  const std::vector<double> ap{1250.0, 25000.0, 50000.0};
  for (std::size_t k = 1; k < 3; ++k) {
    for (std::size_t s = 0; s < g.plane(); ++s) {
      ASSERT_NEAR(got[(k - 1) * g.plane() + s], ap[k] + kB[k] * ps(1, s), 1e-9);
    }
  }
}

TEST(CfFormulaLevelsTest, SigmaCoordinateIsPtopPlusSigmaTimesColumn) {
  TempDir dir;
  const ModelLevels g = levels("atmosphere_sigma_coordinate", "sigma: sigma ps: PS ptop: PTOP");
  sigma_pressure_file(g)
      .variable("sigma", NC_DOUBLE, {"lev"}, {0.125, 0.5, 0.875})
      .variable("PTOP", NC_DOUBLE, {}, {5000.0}, {NcAttr::text_value("units", "Pa")})
      .write(dir / "sigma.nc");
  const InputCatalog c = scan_inputs({dir / "sigma.nc"}, only_t());
  ASSERT_TRUE(c.vertical_geometry);
  EXPECT_EQ(c.vertical_geometry->quantity, Quantity::kPressure);
  const std::vector<double> sigma{0.125, 0.5, 0.875};
  const auto got = read_geometry(c, 0, 0, g.nz);
  for (std::size_t k = 0; k < g.nz; ++k) {
    for (std::size_t s = 0; s < g.plane(); ++s) {
      ASSERT_EQ(got[k * g.plane() + s], 5000.0 + sigma[k] * (ps(0, s) - 5000.0));
    }
  }
}

TEST(CfFormulaLevelsTest, MissingFormulaTermIsRefusedNamingTheTermsNeeded) {
  TempDir dir;
  const ModelLevels g =
      levels("atmosphere_hybrid_sigma_pressure_coordinate", "a: hyam b: hybm p0: P0");
  sigma_pressure_file(g).write(dir / "cam.nc");
  expect_error([&] { scan_inputs({dir / "cam.nc"}, only_t()); }, ErrorCode::kInvalidInput,
               {"cam.nc", "'lev'", "a, b, ps, p0 or ap, b, ps"});
}

TEST(CfFormulaLevelsTest, MissingTermVariableSuggestsFormulaTermFlag) {
  TempDir dir;
  const ModelLevels g =
      levels("atmosphere_hybrid_sigma_pressure_coordinate", "a: hyam b: hybm p0: PZERO ps: PS");
  sigma_pressure_file(g).write(dir / "cam.nc");
  expect_error([&] { scan_inputs({dir / "cam.nc"}, only_t()); }, ErrorCode::kInvalidInput,
               {"cam.nc", "'PZERO'", "--formula-term PZERO=100000"});
  ScanOptions o;
  o.variables = {"T"};
  o.formula_constants = {{"PZERO", 100000.0}};
  const InputCatalog c = scan_inputs({dir / "cam.nc"}, o);
  ASSERT_TRUE(c.vertical_geometry);
  EXPECT_EQ(c.vertical_geometry->constants, (std::map<std::string, double>{{"p0", 100000.0}}));
  const auto got = read_geometry(c, 0, 2, 3, o);
  EXPECT_EQ(got[3], 0.5 * 100000.0 + kB[2] * ps(0, 3));
}

TEST(CfFormulaLevelsTest, TermWithWrongDimensionsIsRefused) {
  TempDir dir;
  const ModelLevels g = levels("atmosphere_hybrid_height_coordinate", "a: a b: blat orog: orog");
  hybrid_height_file(g).variable("blat", NC_DOUBLE, {"lat"}, {0.5, 0.25, 0.0}).write(dir / "um.nc");
  expect_error([&] { scan_inputs({dir / "um.nc"}, only_t()); }, ErrorCode::kInvalidInput,
               {"um.nc", "'blat'", "term 'b'", "(lat)"});
}

TEST(CfFormulaLevelsTest, UnknownFormulaIsRefusedListingTheSupportedOnes) {
  TempDir dir;
  const ModelLevels g =
      levels("ocean_s_coordinate", "s: a eta: orog depth: orog a: a b: b depth_c: a");
  hybrid_height_file(g).write(dir / "roms.nc");
  expect_error([&] { scan_inputs({dir / "roms.nc"}, only_t()); }, ErrorCode::kUnsupported,
               {"roms.nc", "'ocean_s_coordinate'", "atmosphere_hybrid_height_coordinate",
                "atmosphere_hybrid_sigma_pressure_coordinate", "atmosphere_sigma_coordinate"});
}

TEST(CfFormulaLevelsTest, MalformedFormulaTermsAreRefused) {
  TempDir dir;
  const ModelLevels g = levels("atmosphere_hybrid_height_coordinate", "a: a b b orog: orog");
  hybrid_height_file(g).write(dir / "um.nc");
  expect_error([&] { scan_inputs({dir / "um.nc"}, only_t()); }, ErrorCode::kInvalidInput,
               {"um.nc", "'lev'", "formula_terms"});
}

TEST(CfFormulaLevelsTest, SurfacePressureMissingForAStepIsRefused) {
  TempDir dir;
  ModelLevels g =
      levels("atmosphere_hybrid_sigma_pressure_coordinate", "a: hyam b: hybm p0: P0 ps: PS");
  g.nt = 1;
  sigma_pressure_file(g).write(dir / "step0.nc");
  // The second file holds the data of hour 1 but no PS.
  NetcdfFixture(NC_NETCDF4)
      .coordinate("time", {1.0},
                  {NcAttr::text_value("standard_name", "time"),
                   NcAttr::text_value("units", "hours since 2000-01-01")},
                  NC_DOUBLE, true)
      .coordinate("lev", {1.0, 2.0, 3.0}, g.lev_attrs)
      .coordinate("lat", {0.0, 10.0, 20.0},
                  {NcAttr::text_value("standard_name", "latitude"),
                   NcAttr::text_value("units", "degrees_north")})
      .coordinate("lon", g.lon,
                  {NcAttr::text_value("standard_name", "longitude"),
                   NcAttr::text_value("units", "degrees_east")})
      .variable("T", NC_FLOAT, {"time", "lev", "lat", "lon"}, testing::ramp(g.nz * g.plane()),
                {NcAttr::text_value("units", "K")})
      .write(dir / "step1.nc");
  expect_error(
      [&] {
        scan_inputs({dir / "step0.nc", dir / "step1.nc"}, only_t());
      },
      ErrorCode::kInvalidInput, {"step1.nc", "'PS'", "time step 1", "step0.nc"});
}

TEST(CfFormulaLevelsTest, FillValueInSurfacePressureNamesTheSample) {
  TempDir dir;
  const ModelLevels g =
      levels("atmosphere_hybrid_sigma_pressure_coordinate", "a: hyam b: hybm p0: P0 ps: PS");
  auto values =
      field(g.nt, 1, g.plane(), [](std::size_t t, std::size_t, std::size_t s) { return ps(t, s); });
  values[g.plane() + 2 * g.nx + 1] = 1e20;  // t 1, j 2, i 1
  g.fixture()
      .variable("hyam", NC_DOUBLE, {"lev"}, {0.0125, 0.25, 0.5})
      .variable("hybm", NC_DOUBLE, {"lev"}, kB)
      .variable("P0", NC_DOUBLE, {}, {100000.0})
      .variable(
          "PS", NC_DOUBLE, {"time", "lat", "lon"}, values,
          {NcAttr::text_value("units", "Pa"), NcAttr::number("missing_value", NC_DOUBLE, {1e20})})
      .write(dir / "cam.nc");
  const InputCatalog c = scan_inputs({dir / "cam.nc"}, only_t());
  EXPECT_NO_THROW(read_geometry(c, 0, 0, g.nz));
  expect_error([&] { read_geometry(c, 1, 0, 1); }, ErrorCode::kInvalidInput,
               {"cam.nc", "'PS'", "time step 1", "(i 1, j 2, k 0)"});
}

}  // namespace
}  // namespace strielad::ingest
