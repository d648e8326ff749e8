// SPDX-License-Identifier: Apache-2.0
// cdf/contour.cdf: no axis attributes, forecast time "frtime" in plain "hours", millibar
// levels, _FillValue -9999 and valid_range on T and Z, a 2D Psl and 2D grib_* integers.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/expect_error.h"
#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using strielad::testing::expect_error;
using strielad::testing::ncarg_file;
using strielad::testing::read_vara;

const auto kFile = ncarg_file("cdf/contour.cdf");

TEST(NcargContourCdfTest, DetectsAxesWithoutAxisAttributes) {
  const InputCatalog c = scan_inputs({kFile}, {});
  EXPECT_EQ(c.dims(), (Dims3{36, 33, 10}));
  EXPECT_EQ(c.x.name, "lon");
  EXPECT_EQ(c.x.values.front(), -140.0);
  EXPECT_EQ(c.x.values.back(), -52.5);
  EXPECT_EQ(c.y.name, "lat");
  EXPECT_FALSE(c.y.descending());
  EXPECT_EQ(c.z.name, "level");
  EXPECT_EQ(c.z.kind, AxisKind::kPressure);
  EXPECT_EQ(c.z.units, "millibars");
  EXPECT_EQ(c.z.values, (std::vector<double>{1000, 850, 700, 500, 400, 300, 250, 200, 150, 100}));
  EXPECT_EQ(c.time.name, "frtime");
  EXPECT_EQ(c.time.units, "hours");
  EXPECT_EQ(c.time.values, (std::vector<double>{0, 6, 12, 24, 30, 36, 48}));
}

TEST(NcargContourCdfTest, DefaultSelectionSkips2DVariables) {
  const InputCatalog c = scan_inputs({kFile}, {});
  ASSERT_EQ(c.variables.size(), 2u);
  EXPECT_EQ(c.variables[0].name, "T");
  EXPECT_EQ(c.variables[1].name, "Z");
  ASSERT_EQ(c.locations[1].size(), 7u);
  EXPECT_EQ(c.locations[1][4].time_in_file, 4u);
}

TEST(NcargContourCdfTest, Requested2DVariableIsUnsupported) {
  ScanOptions o;
  o.variables = {"Psl"};
  expect_error([&] { scan_inputs({kFile}, o); }, ErrorCode::kUnsupported,
               {"contour.cdf", "'Psl'", "no vertical dimension"});
}

TEST(NcargContourCdfTest, FillAndValidRangeAttributesAreRead) {
  const InputCatalog c = scan_inputs({kFile}, {});
  const VariableMeta& t = c.variables[0];
  EXPECT_EQ(t.units, "degK");
  EXPECT_EQ(t.long_name, "temperature");
  EXPECT_EQ(t.fill_value, -9999.0);
  EXPECT_EQ(t.valid_min, 0.0);
  EXPECT_EQ(t.valid_max, 400.0);
  EXPECT_EQ(t.store_type, DType::kFloat32);
  const VariableMeta& z = c.variables[1];
  EXPECT_EQ(z.valid_min, -150.0);
  EXPECT_EQ(z.valid_max, 5000.0);
}

TEST(NcargContourCdfTest, SamplesOutsideValidRangeBecomeNaN) {
  const InputCatalog c = scan_inputs({kFile}, {});
  SlabReader reader(c, {});
  const Dims3 d = c.dims();
  std::vector<float> z(d.count());
  reader.read(1, 5, 0, d.z, z);
  const auto raw = read_vara(kFile, "Z", {5, 0, 0, 0}, {1, d.z, d.y, d.x});
  std::size_t masked = 0;
  for (std::size_t i = 0; i < z.size(); ++i) {
    if (raw[i] == -9999.0 || raw[i] < -150.0 || raw[i] > 5000.0) {
      ASSERT_TRUE(std::isnan(z[i])) << "sample " << i << " raw " << raw[i];
      ++masked;
    } else {
      ASSERT_EQ(z[i], static_cast<float>(raw[i])) << "sample " << i;
    }
  }
  EXPECT_GT(masked, 0u);  // upper-level heights exceed valid_max 5000
  std::vector<float> t(d.count());
  reader.read(0, 6, 0, d.z, t);
  const auto raw_t = read_vara(kFile, "T", {6, 0, 0, 0}, {1, d.z, d.y, d.x});
  for (std::size_t i = 0; i < t.size(); ++i) {
    ASSERT_EQ(t[i], static_cast<float>(raw_t[i])) << "sample " << i;
  }
}

}  // namespace
}  // namespace strielad::ingest
