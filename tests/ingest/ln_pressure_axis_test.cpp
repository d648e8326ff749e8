// SPDX-License-Identifier: Apache-2.0
// CF atmosphere_ln_pressure_coordinate (p = p0 * exp(-lev)): the z axis becomes a plain
// pressure axis in Pa, exactly p0 * exp(-lev) per level, without a geometry field, and a
// converted store is a pressure-level store; refused, naming the coordinate and term: a
// missing p0 or lev term, a term variable the file lacks, p0 not positive or not a
// pressure, pressures not strictly monotonic.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "convert/converter.h"
#include "ingest/input_catalog.h"
#include "ingest/ln_pressure_axis.h"
#include "store/store.h"
#include "support/expect_error.h"
#include "support/model_levels_fixture.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using strielad::testing::expect_error;
using strielad::testing::ModelLevels;
using strielad::testing::NcAttr;
using strielad::testing::NetcdfFixture;
using strielad::testing::TempDir;

// lev (1, 2, 3 from the fixture) as atmosphere_ln_pressure_coordinate.
ModelLevels ln_levels(const std::string& formula_terms) {
  ModelLevels g;
  g.lev_attrs.push_back(NcAttr::text_value("standard_name", "atmosphere_ln_pressure_coordinate"));
  g.lev_attrs.push_back(NcAttr::text_value("formula_terms", formula_terms));
  return g;
}

NetcdfFixture ln_file(const ModelLevels& g, double p0 = 1000.0, const std::string& units = "hPa") {
  return g.fixture().variable("P0", NC_DOUBLE, {}, {p0}, {NcAttr::text_value("units", units)});
}

ScanOptions only_t() {
  ScanOptions o;
  o.variables = {"T"};
  return o;
}

TEST(LnPressureAxisTest, LevelsBecomeAPressureAxisInPascals) {
  TempDir dir;
  ln_file(ln_levels("p0: P0 lev: lev")).write(dir / "ln.nc");
  const InputCatalog c = scan_inputs({dir / "ln.nc"}, {});
  EXPECT_EQ(c.z.name, "lev");
  EXPECT_EQ(c.z.kind, AxisKind::kPressure);
  EXPECT_EQ(c.z.units, "Pa");
  EXPECT_EQ(c.z.standard_name, "air_pressure");
  EXPECT_EQ(c.z.positive, "down");
  // p0 1000 hPa: 100000 Pa, exactly.
  EXPECT_EQ(c.z.values, (std::vector<double>{100000.0 * std::exp(-1.0), 100000.0 * std::exp(-2.0),
                                             100000.0 * std::exp(-3.0)}));
  // The pressures are the levels: no per-sample geometry to store.
  EXPECT_FALSE(c.vertical_geometry);
  // P0 is a scalar, not converted; T is the only data variable.
  ASSERT_EQ(c.variables.size(), 1u);
  EXPECT_EQ(c.variables[0].name, "T");
}

TEST(LnPressureAxisTest, ConvertsToAPressureLevelStore) {
  TempDir dir;
  ln_file(ln_levels("p0: P0 lev: lev"), 100000.0, "Pa").write(dir / "ln.nc");
  build::ConvertOptions o;
  o.inputs = {dir / "ln.nc"};
  o.store = dir / "store";
  o.brick = 8;
  o.threads = 1;
  build::convert(o);
  const auto store = Store::open(dir / "store");
  const format::Manifest& m = store->manifest();
  EXPECT_EQ(m.z.kind, AxisKind::kPressure);
  EXPECT_EQ(m.z.units, "Pa");
  EXPECT_EQ(m.z.values[2], 100000.0 * std::exp(-3.0));
  EXPECT_FALSE(m.geometry);
}

TEST(LnPressureAxisTest, MissingTermIsRefusedNamingIt) {
  TempDir dir;
  ln_file(ln_levels("lev: lev")).write(dir / "no_p0.nc");
  expect_error([&] { scan_inputs({dir / "no_p0.nc"}, only_t()); }, ErrorCode::kInvalidInput,
               {"no_p0.nc", "'lev'", "atmosphere_ln_pressure_coordinate", "no 'p0' term"});
  ln_file(ln_levels("p0: P0")).write(dir / "no_lev.nc");
  expect_error([&] { scan_inputs({dir / "no_lev.nc"}, only_t()); }, ErrorCode::kInvalidInput,
               {"no_lev.nc", "no 'lev' term"});
  // Refused by default selection too: the only 3-D variable cannot be placed.
  expect_error([&] { scan_inputs({dir / "no_lev.nc"}, {}); }, ErrorCode::kInvalidInput,
               {"no_lev.nc", "no 'lev' term"});
}

TEST(LnPressureAxisTest, TermVariableTheFileLacksIsRefusedNamingIt) {
  TempDir dir;
  ln_file(ln_levels("p0: PZERO lev: lev")).write(dir / "ln.nc");
  expect_error([&] { scan_inputs({dir / "ln.nc"}, only_t()); }, ErrorCode::kInvalidInput,
               {"ln.nc", "term 'p0'", "'PZERO'", "does not hold"});
}

TEST(LnPressureAxisTest, NonPositiveP0IsRefused) {
  TempDir dir;
  ln_file(ln_levels("p0: P0 lev: lev"), 0.0).write(dir / "zero.nc");
  expect_error([&] { scan_inputs({dir / "zero.nc"}, only_t()); }, ErrorCode::kInvalidInput,
               {"zero.nc", "'lev'", "p0 is 0 Pa", "positive p0"});
  ln_file(ln_levels("p0: P0 lev: lev"), -1000.0).write(dir / "negative.nc");
  expect_error([&] { scan_inputs({dir / "negative.nc"}, only_t()); }, ErrorCode::kInvalidInput,
               {"negative.nc", "p0 is -100000 Pa"});
  ln_file(ln_levels("p0: P0 lev: lev"), 1000.0, "m").write(dir / "metres.nc");
  expect_error([&] { scan_inputs({dir / "metres.nc"}, only_t()); }, ErrorCode::kInvalidInput,
               {"metres.nc", "'P0'", "units 'm'", "not a pressure unit"});
}

TEST(LnPressureAxisTest, NonMonotonicPressuresAreRefused) {
  TempDir dir;
  ln_file(ln_levels("p0: P0 lev: ln_lev"))
      .variable("ln_lev", NC_DOUBLE, {"lev"}, {1.0, 3.0, 2.0})
      .write(dir / "ln.nc");
  expect_error([&] { scan_inputs({dir / "ln.nc"}, only_t()); }, ErrorCode::kInvalidInput,
               {"ln.nc", "'lev'", "levels 0 .. 2", "not strictly monotonic"});

  const std::vector<double> same{1.0, 2.0, 2.0};
  expect_error([&] { ln_pressure_levels(1e5, same, "f.nc: z coordinate 'lev'"); },
               ErrorCode::kInvalidInput,
               {"f.nc: z coordinate 'lev'", "levels 1 and 2", "the same pressure"});
  const std::vector<double> overflow{-800.0, 1.0};
  expect_error([&] { ln_pressure_levels(1e5, overflow, "c"); }, ErrorCode::kInvalidInput,
               {"level 0 (lev -800)", "not a positive finite pressure"});
  const std::vector<double> nan{1.0, std::nan("")};
  expect_error([&] { ln_pressure_levels(1e5, nan, "c"); }, ErrorCode::kInvalidInput,
               {"lev of level 1", "not a finite number"});
}

TEST(LnPressureAxisTest, LevTermOffTheCoordinatesDimensionIsRefused) {
  TempDir dir;
  ln_file(ln_levels("p0: P0 lev: lat_lev"))
      .variable("lat_lev", NC_DOUBLE, {"lat"}, {1.0, 2.0, 3.0})
      .write(dir / "ln.nc");
  expect_error([&] { scan_inputs({dir / "ln.nc"}, only_t()); }, ErrorCode::kInvalidInput,
               {"ln.nc", "lev variable 'lat_lev'", "dimension of 'lev'"});
}

}  // namespace
}  // namespace strielad::ingest
