// SPDX-License-Identifier: Apache-2.0
// Packed integers (scale_factor/add_offset) unpack exactly; _FillValue is compared in the
// packed type before unpacking.
#include <gtest/gtest.h>

#include <cmath>

#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "support/expect_error.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

std::vector<double> packed_raw(std::size_t n) {
  std::vector<double> raw(n);
  for (std::size_t i = 0; i < n; ++i) raw[i] = static_cast<double>(i * 997 % 60000) - 30000.0;
  raw[5] = -32767;  // fill
  return raw;
}

TEST(PackedDataUnpackingTest, ShortWithFloatScaleRoundTripsToFloat) {
  TempDir dir;
  SimpleGrid g;
  const auto raw = packed_raw(g.samples());
  const float scale = 0.0123f, offset = 273.15f;
  NetcdfFixture()
      .grid(g)
      .variable("t", NC_SHORT, g.dims(), raw,
                {NcAttr::number("scale_factor", NC_FLOAT, {scale}),
                 NcAttr::number("add_offset", NC_FLOAT, {offset}),
                 NcAttr::number("_FillValue", NC_SHORT, {-32767})})
      .write(dir / "packed.nc");
  const InputCatalog c = scan_inputs({dir / "packed.nc"}, {});
  const VariableMeta& m = c.variables[0];
  EXPECT_EQ(m.source_type, "short");
  EXPECT_EQ(m.store_type, DType::kFloat32);
  EXPECT_EQ(m.scale_factor, static_cast<double>(scale));
  EXPECT_EQ(m.add_offset, static_cast<double>(offset));
  EXPECT_EQ(m.fill_value, -32767.0);

  SlabReader reader(c, {});
  std::vector<float> out(g.samples());
  reader.read(0, 0, 0, 2, out);
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (i == 5) {
      EXPECT_TRUE(std::isnan(out[i]));
      continue;
    }
    const float expected =
        static_cast<float>(raw[i] * static_cast<double>(scale) + static_cast<double>(offset));
    ASSERT_EQ(out[i], expected) << "sample " << i << " raw " << raw[i];
  }
}

TEST(PackedDataUnpackingTest, ShortWithDoubleScaleIsStoredAsDouble) {
  TempDir dir;
  SimpleGrid g;
  const auto raw = packed_raw(g.samples());
  NetcdfFixture()
      .grid(g)
      .variable("q", NC_SHORT, g.dims(), raw,
                {NcAttr::number("scale_factor", NC_DOUBLE, {1e-7}),
                 NcAttr::number("add_offset", NC_DOUBLE, {0.003}),
                 NcAttr::number("_FillValue", NC_SHORT, {-32767})})
      .write(dir / "packed.nc");
  const InputCatalog c = scan_inputs({dir / "packed.nc"}, {});
  EXPECT_EQ(c.variables[0].store_type, DType::kFloat64);
  SlabReader reader(c, {});
  std::vector<double> out(g.samples());
  reader.read(0, 0, 0, 2, out);
  EXPECT_TRUE(std::isnan(out[5]));
  EXPECT_EQ(out[0], raw[0] * 1e-7 + 0.003);
  EXPECT_EQ(out[7], raw[7] * 1e-7 + 0.003);
}

TEST(PackedDataUnpackingTest, FillIsComparedBeforeUnpacking) {
  TempDir dir;
  SimpleGrid g;
  std::vector<double> raw(g.samples(), 10.0);
  raw[3] = 0.0;  // the packed fill; unpacks to add_offset, which is an ordinary value
  raw[4] = -5.0;
  NetcdfFixture()
      .grid(g)
      .variable("u", NC_BYTE, g.dims(), raw,
                {NcAttr::number("scale_factor", NC_FLOAT, {0.5}),
                 NcAttr::number("add_offset", NC_FLOAT, {-5}),
                 NcAttr::number("_FillValue", NC_BYTE, {0})})
      .write(dir / "packed.nc");
  const InputCatalog c = scan_inputs({dir / "packed.nc"}, {});
  SlabReader reader(c, {});
  std::vector<float> out(g.samples());
  reader.read(0, 0, 0, 2, out);
  EXPECT_TRUE(std::isnan(out[3]));
  EXPECT_EQ(out[4], -7.5f);
  EXPECT_EQ(out[0], 0.0f);
}

// A scale_factor that unpacks beyond float32 used to store +-Inf; now an error naming the
// sample (docs/robustness.md, "packed-overflow"), with or without nan_as_fill.
TEST(PackedDataUnpackingTest, UnpackingBeyondFloat32IsRefused) {
  TempDir dir;
  SimpleGrid g;
  std::vector<double> raw(g.samples(), 1.0);
  raw[0] = 0.0;
  raw[6] = 400.0;  // 400 x 1e36 = 4e38 > 3.4e38: lon 2, lat 1, level 0
  raw[7] = -32767;
  NetcdfFixture()
      .grid(g)
      .variable("p", NC_SHORT, g.dims(), raw,
                {NcAttr::number("scale_factor", NC_FLOAT, {1e36}),
                 NcAttr::number("_FillValue", NC_SHORT, {-32767})})
      .write(dir / "packed.nc");
  for (const bool nan_as_fill : {false, true}) {
    ScanOptions o;
    o.nan_as_fill = nan_as_fill;
    const InputCatalog c = scan_inputs({dir / "packed.nc"}, o);
    SlabReader reader(c, o);
    std::vector<float> out(g.samples());
    expect_error([&] { reader.read(0, 0, 0, 2, out); }, ErrorCode::kInvalidInput,
                 {"variable 'p' time step 0: sample (lon 2, lat 1, level 0) unpacks to",
                  "beyond the range of float32"});
  }
}

}  // namespace
}  // namespace strielad::ingest
