// SPDX-License-Identifier: Apache-2.0
// cdf/vinth2p.nc: CAM hybrid sigma-pressure levels ("hybrid_sigma_pressure" units, no
// standard_name), two time steps, surface pressure PS (2D) and hyam/hybm (1D) alongside.
// The CCM attributes of lev (A_var hyam, B_var hybm, P0_var P0, PS_var PS) give each
// sample's pressure, but the file lacks P0: it is refused until P0 is given.
#include <gtest/gtest.h>

#include <vector>

#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "support/expect_error.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using strielad::testing::expect_error;
using strielad::testing::ncarg_file;
using strielad::testing::read_vara;

const auto kFile = ncarg_file("cdf/vinth2p.nc");

ScanOptions with_p0() {
  ScanOptions o;
  o.formula_constants = {{"P0", 100000.0}};
  return o;
}

TEST(NcargHybridLevelsTest, ScansHybridLevelsAsModelLevels) {
  const InputCatalog c = scan_inputs({kFile}, with_p0());
  ASSERT_EQ(c.variables.size(), 1u);
  EXPECT_EQ(c.variables[0].name, "T");
  // 128 longitudes round the Earth: the first meridian is repeated at the end.
  EXPECT_EQ(c.dims(), (Dims3{129, 64, 18}));
  EXPECT_TRUE(c.x.periodic);
  EXPECT_EQ(c.x.values.back(), c.x.values.front() + 360.0);
  EXPECT_EQ(c.z.kind, AxisKind::kModelLevel);
  EXPECT_EQ(c.z.positive, "down");
  EXPECT_EQ(c.z.units, "hybrid_sigma_pressure");
  EXPECT_FALSE(c.z.descending());
  EXPECT_EQ(c.time.units, "days since 0049-09-01 00:00:00");
  EXPECT_EQ(c.time.values, (std::vector<double>{107, 108}));
}

TEST(NcargHybridLevelsTest, ReadsSecondStep) {
  const InputCatalog c = scan_inputs({kFile}, with_p0());
  SlabReader reader(c, {});
  std::vector<float> level(64 * 129);
  reader.read(0, 1, 17, 18, level);
  const auto raw = read_vara(kFile, "T", {1, 17, 0, 0}, {1, 1, 64, 128});
  for (std::size_t j = 0; j < 64; ++j) {
    for (std::size_t i = 0; i <= 128; ++i) {  // column 128 repeats column 0
      ASSERT_EQ(level[j * 129 + i], static_cast<float>(raw[j * 128 + i % 128])) << i << ", " << j;
    }
  }
}

TEST(NcargHybridLevelsTest, WithoutP0IsRefusedNamingP0VarAndTheFormulaTermFlag) {
  expect_error([] { scan_inputs({kFile}, {}); }, ErrorCode::kInvalidInput,
               {"vinth2p.nc", "P0_var", "'P0'", "--formula-term P0=100000"});
}

TEST(NcargHybridLevelsTest, PressureIsHyamTimesP0PlusHybmTimesPs) {
  const InputCatalog c = scan_inputs({kFile}, with_p0());
  ASSERT_TRUE(c.vertical_geometry);
  const VerticalGeometrySource& v = *c.vertical_geometry;
  EXPECT_EQ(v.quantity, VerticalGeometrySource::Quantity::kPressure);
  EXPECT_EQ(v.formula, "atmosphere_hybrid_sigma_pressure_coordinate");
  EXPECT_EQ(v.terms,
            (std::map<std::string, std::string>{{"a", "hyam"}, {"b", "hybm"}, {"ps", "PS"}}));
  EXPECT_EQ(v.constants, (std::map<std::string, double>{{"p0", 100000.0}}));
  EXPECT_TRUE(v.varies_in_time);

  const auto hyam = read_vara(kFile, "hyam", {0}, {18});
  const auto hybm = read_vara(kFile, "hybm", {0}, {18});
  SlabReader reader(c, {});
  for (std::size_t t : {0u, 1u}) {
    const auto ps = read_vara(kFile, "PS", {t, 0, 0}, {1, 64, 128});
    std::vector<double> p(18 * 64 * 129);
    reader.read_vertical_geometry(t, 0, 18, p);
    for (std::size_t k : {0u, 9u, 17u}) {
      for (auto [i, j] :
           {std::pair<std::size_t, std::size_t>{0, 0}, {5, 7}, {127, 63}, {128, 30}}) {
        const double want = hyam[k] * 100000.0 + hybm[k] * ps[j * 128 + i % 128];
        ASSERT_DOUBLE_EQ(p[(k * 64 + j) * 129 + i], want)
            << "t " << t << " k " << k << " i " << i << " j " << j;
      }
    }
  }
  // The steps differ: PS varies in time.
  std::vector<double> p0(64 * 129), p1(64 * 129);
  reader.read_vertical_geometry(0, 17, 18, p0);
  reader.read_vertical_geometry(1, 17, 18, p1);
  EXPECT_NE(p0, p1);
}

}  // namespace
}  // namespace strielad::ingest
