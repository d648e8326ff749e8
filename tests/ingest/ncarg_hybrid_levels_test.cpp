// SPDX-License-Identifier: Apache-2.0
// cdf/vinth2p.nc: CAM hybrid sigma-pressure levels ("hybrid_sigma_pressure" units, no
// standard_name), two time steps, surface pressure PS (2D) and hyam/hybm (1D) alongside.
#include <gtest/gtest.h>

#include <vector>

#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using strielad::testing::ncarg_file;
using strielad::testing::read_vara;

const auto kFile = ncarg_file("cdf/vinth2p.nc");

TEST(NcargHybridLevelsTest, ScansHybridLevelsAsModelLevels) {
  const InputCatalog c = scan_inputs({kFile}, {});
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
  const InputCatalog c = scan_inputs({kFile}, {});
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

}  // namespace
}  // namespace strielad::ingest
