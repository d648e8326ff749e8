// SPDX-License-Identifier: Apache-2.0
// The store type keeps every source type's unpacked values exactly.
#include <gtest/gtest.h>

#include <netcdf.h>

#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "ingest/variable_meta.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

TEST(StoreTypeRuleTest, PlainTypes) {
  EXPECT_EQ(store_type_for(NC_FLOAT, std::nullopt), DType::kFloat32);
  EXPECT_EQ(store_type_for(NC_DOUBLE, std::nullopt), DType::kFloat64);
  for (int t : {NC_BYTE, NC_SHORT, NC_UBYTE, NC_USHORT}) {
    EXPECT_EQ(store_type_for(t, std::nullopt), DType::kFloat32) << t;
  }
  for (int t : {NC_INT, NC_UINT, NC_INT64, NC_UINT64}) {
    EXPECT_EQ(store_type_for(t, std::nullopt), DType::kFloat64) << t;
  }
}

TEST(StoreTypeRuleTest, PackedTypesFollowTheScaleFactor) {
  EXPECT_EQ(store_type_for(NC_SHORT, NC_FLOAT), DType::kFloat32);
  EXPECT_EQ(store_type_for(NC_SHORT, NC_DOUBLE), DType::kFloat64);
  EXPECT_EQ(store_type_for(NC_INT, NC_FLOAT), DType::kFloat32);
  EXPECT_EQ(store_type_for(NC_BYTE, NC_DOUBLE), DType::kFloat64);
  EXPECT_EQ(store_type_for(NC_SHORT, NC_INT), DType::kFloat64);
}

TEST(StoreTypeRuleTest, ScannedVariablesGetTheirStoreType) {
  TempDir dir;
  SimpleGrid g;
  const auto data = ramp(g.samples());
  NetcdfFixture(NC_NETCDF4)
      .grid(g)
      .variable("f", NC_FLOAT, g.dims(), data)
      .variable("d", NC_DOUBLE, g.dims(), data)
      .variable("b", NC_BYTE, g.dims(), data)
      .variable("us", NC_USHORT, g.dims(), data)
      .variable("i", NC_INT, g.dims(), data)
      .variable("i64", NC_INT64, g.dims(), data)
      .write(dir / "types.nc");
  const InputCatalog c = scan_inputs({dir / "types.nc"}, {});
  auto meta = [&](const char* n) { return c.variables[c.variable_index(n)]; };
  EXPECT_EQ(meta("f").store_type, DType::kFloat32);
  EXPECT_EQ(meta("d").store_type, DType::kFloat64);
  EXPECT_EQ(meta("d").source_type, "double");
  EXPECT_EQ(meta("b").store_type, DType::kFloat32);
  EXPECT_EQ(meta("b").source_type, "byte");
  EXPECT_EQ(meta("us").store_type, DType::kFloat32);
  EXPECT_EQ(meta("us").source_type, "ushort");
  EXPECT_EQ(meta("i").store_type, DType::kFloat64);
  EXPECT_EQ(meta("i64").store_type, DType::kFloat64);
  EXPECT_EQ(meta("i64").source_type, "int64");

  SlabReader reader(c, {});
  std::vector<double> out(g.samples());
  reader.read(c.variable_index("d"), 0, 0, 2, out);
  EXPECT_EQ(out, data);
  reader.read(c.variable_index("i64"), 0, 0, 2, out);
  EXPECT_EQ(out, data);
  std::vector<float> f(g.samples());
  reader.read(c.variable_index("d"), 0, 0, 2, f);  // float64 variable read into floats
  EXPECT_EQ(f[7], 7.0f);
}

}  // namespace
}  // namespace strielad::ingest
