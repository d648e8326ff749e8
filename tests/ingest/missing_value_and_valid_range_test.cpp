// SPDX-License-Identifier: Apache-2.0
// missing_value (all of its values), valid_min/valid_max/valid_range and the netCDF
// default fill mark samples missing (NaN).
#include <gtest/gtest.h>

#include <netcdf.h>

#include <cmath>

#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

std::vector<float> read_all(const std::filesystem::path& path, InputCatalog* out = nullptr) {
  const InputCatalog c = scan_inputs({path}, {});
  SlabReader reader(c, {});
  std::vector<float> v(c.dims().count());
  reader.read(0, 0, 0, c.dims().z, v);
  if (out) *out = c;
  return v;
}

TEST(MissingValueAndValidRangeTest, EveryMissingValueIsNaN) {
  TempDir dir;
  SimpleGrid g;
  auto data = ramp(g.samples(), 1.0);
  data[2] = -1;
  data[9] = -2;
  NetcdfFixture()
      .grid(g)
      .variable("T", NC_FLOAT, g.dims(), data,
                {NcAttr::number("missing_value", NC_FLOAT, {-1, -2})})
      .write(dir / "mv.nc");
  InputCatalog c;
  const auto v = read_all(dir / "mv.nc", &c);
  EXPECT_EQ(c.variables[0].missing_value, -1.0);
  EXPECT_EQ(c.variables[0].missing_values, (std::vector<double>{-1, -2}));
  EXPECT_TRUE(std::isnan(v[2]));
  EXPECT_TRUE(std::isnan(v[9]));
  EXPECT_EQ(v[3], 4.0f);
}

TEST(MissingValueAndValidRangeTest, OutsideValidMinMaxIsNaN) {
  TempDir dir;
  SimpleGrid g;
  const auto data = ramp(g.samples());
  NetcdfFixture()
      .grid(g)
      .variable("T", NC_INT, g.dims(), data,
                {NcAttr::number("valid_min", NC_INT, {3}), NcAttr::number("valid_max", NC_INT, {20})})
      .write(dir / "vr.nc");
  InputCatalog c;
  const auto v = read_all(dir / "vr.nc", &c);
  EXPECT_EQ(c.variables[0].valid_min, 3.0);
  EXPECT_EQ(c.variables[0].valid_max, 20.0);
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i < 3 || i > 20) {
      EXPECT_TRUE(std::isnan(v[i])) << i;
    } else {
      EXPECT_EQ(v[i], static_cast<float>(i));
    }
  }
}

TEST(MissingValueAndValidRangeTest, ValidRangeIsInPackedUnits) {
  TempDir dir;
  SimpleGrid g;
  const auto data = ramp(g.samples());
  NetcdfFixture()
      .grid(g)
      .variable("T", NC_SHORT, g.dims(), data,
                {NcAttr::number("scale_factor", NC_FLOAT, {10}),
                 NcAttr::number("valid_range", NC_SHORT, {0, 5})})
      .write(dir / "vr.nc");
  const auto v = read_all(dir / "vr.nc");
  EXPECT_EQ(v[5], 50.0f);
  EXPECT_TRUE(std::isnan(v[6]));
}

TEST(MissingValueAndValidRangeTest, DefaultFillCountsWithoutFillValueAttribute) {
  TempDir dir;
  SimpleGrid g;
  auto data = ramp(g.samples());
  data[4] = NC_FILL_FLOAT;
  NetcdfFixture().grid(g).variable("T", NC_FLOAT, g.dims(), data).write(dir / "df.nc");
  InputCatalog c;
  const auto v = read_all(dir / "df.nc", &c);
  EXPECT_FALSE(c.variables[0].fill_value.has_value());
  EXPECT_TRUE(std::isnan(v[4]));
  EXPECT_EQ(v[5], 5.0f);
}

TEST(MissingValueAndValidRangeTest, ExplicitFillValueReplacesTheDefault) {
  TempDir dir;
  SimpleGrid g;
  auto data = ramp(g.samples());
  data[4] = NC_FILL_FLOAT;
  data[6] = -1;
  NetcdfFixture()
      .grid(g)
      .variable("T", NC_FLOAT, g.dims(), data, {NcAttr::number("_FillValue", NC_FLOAT, {-1})})
      .write(dir / "df.nc");
  const auto v = read_all(dir / "df.nc");
  EXPECT_EQ(v[4], NC_FILL_FLOAT);
  EXPECT_TRUE(std::isnan(v[6]));
}

}  // namespace
}  // namespace strielad::ingest
