// SPDX-License-Identifier: Apache-2.0
// cdf/nc4uvt.nc: NetCDF-4 with NC_STRING attributes, an int "lev" in hPa, _FillValue -999,
// and the same variables again in group grp1.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using strielad::testing::ncarg_file;
using strielad::testing::read_vara;

const auto kFile = ncarg_file("cdf/nc4uvt.nc");

TEST(NcargNetcdf4GroupsTest, IntegerPressureLevelsWithStringAttributes) {
  const InputCatalog c = scan_inputs({kFile}, {});
  // 128 longitudes round the Earth (-180 .. 177.1875): the first meridian is repeated.
  EXPECT_EQ(c.dims(), (Dims3{129, 64, 14}));
  EXPECT_TRUE(c.x.periodic);
  EXPECT_EQ(c.x.values.back(), 180.0);
  EXPECT_EQ(c.z.name, "lev");
  EXPECT_EQ(c.z.kind, AxisKind::kPressure);
  EXPECT_EQ(c.z.units, "hPa");
  EXPECT_EQ(c.z.long_name, "Pressure");
  EXPECT_EQ(c.z.values.front(), 1000.0);
  EXPECT_EQ(c.z.values.back(), 10.0);
  EXPECT_EQ(c.y.units, "degrees_north");
  EXPECT_FALSE(c.y.descending());
  EXPECT_EQ(c.time.units, "Month");
  EXPECT_EQ(c.time.values, std::vector<double>{0.0});
}

TEST(NcargNetcdf4GroupsTest, DefaultSelectionIncludesGroupVariables) {
  const InputCatalog c = scan_inputs({kFile}, {});
  std::vector<std::string> names;
  for (const auto& v : c.variables) names.push_back(v.name);
  EXPECT_EQ(names, (std::vector<std::string>{"T", "U", "V", "grp1/T", "grp1/U", "grp1/V"}));
  const VariableMeta& t = c.variables[0];
  EXPECT_EQ(t.units, "C");
  EXPECT_EQ(t.long_name, "Temperature");
  EXPECT_EQ(t.fill_value, -999.0);
}

TEST(NcargNetcdf4GroupsTest, GroupVariableIsAddressableAndFillBecomesNaN) {
  ScanOptions o;
  o.variables = {"grp1/T"};
  const InputCatalog c = scan_inputs({kFile}, o);
  ASSERT_EQ(c.variables.size(), 1u);
  EXPECT_EQ(c.variables[0].name, "grp1/T");
  EXPECT_EQ(c.variable_index("grp1/T"), 0u);

  SlabReader reader(c, o);
  std::vector<float> all(c.dims().count());
  reader.read(0, 0, 0, 14, all);
  const auto raw = strielad::testing::with_repeated_first_column(
      read_vara(kFile, "grp1/T", {0, 0, 0, 0}, {1, 14, 64, 128}), 128);
  std::size_t fills = 0;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (raw[i] == -999.0) {
      ASSERT_TRUE(std::isnan(all[i])) << "sample " << i;
      ++fills;
    } else {
      ASSERT_EQ(all[i], static_cast<float>(raw[i])) << "sample " << i;
    }
  }
  EXPECT_EQ(fills, 0u);  // the file declares _FillValue -999 but uses none
  EXPECT_EQ(c.variables[0].fill_value, -999.0);
}

TEST(NcargNetcdf4GroupsTest, NestedGroupWithStringAttributesAndFill) {
  strielad::testing::TempDir dir;
  strielad::testing::SimpleGrid g;
  g.group = "g/sub";
  auto data = strielad::testing::ramp(g.samples());
  data[7] = -999;
  using strielad::testing::NcAttr;
  strielad::testing::NetcdfFixture(NC_NETCDF4)
      .grid(g)
      .variable("g/sub/T", NC_FLOAT, g.dims(), data,
                {NcAttr::number("_FillValue", NC_FLOAT, {-999}),
                 NcAttr::string_value("units", "K"),
                 NcAttr::string_value("standard_name", "air_temperature")})
      .write(dir / "nested.nc");
  const InputCatalog c = scan_inputs({dir / "nested.nc"}, {});
  ASSERT_EQ(c.variables.size(), 1u);
  EXPECT_EQ(c.variables[0].name, "g/sub/T");
  EXPECT_EQ(c.variables[0].units, "K");
  EXPECT_EQ(c.variables[0].standard_name, "air_temperature");
  SlabReader reader(c, {});
  std::vector<float> out(g.samples());
  reader.read(0, 0, 0, 2, out);
  EXPECT_TRUE(std::isnan(out[7]));
  EXPECT_EQ(out[8], 8.0f);
}

TEST(NcargNetcdf4GroupsTest, LeadingSlashNamesTheSameVariable) {
  ScanOptions o;
  o.variables = {"/grp1/U", "V"};
  const InputCatalog c = scan_inputs({kFile}, o);
  ASSERT_EQ(c.variables.size(), 2u);
  EXPECT_EQ(c.variables[0].name, "grp1/U");
  EXPECT_EQ(c.variables[1].name, "V");
}

}  // namespace
}  // namespace strielad::ingest
