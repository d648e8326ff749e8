// SPDX-License-Identifier: Apache-2.0
// nug/rectilinear_grid_3D.nc (ECHAM5 via CDO): 192 x 96 x 17 Pa levels, latitude north to
// south, three float variables, one time step.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/checksum.h"
#include "core/file_io.h"
#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using strielad::testing::ncarg_file;
using strielad::testing::read_vara;
using strielad::testing::with_repeated_first_column;

const auto kFile = ncarg_file("nug/rectilinear_grid_3D.nc");

TEST(NcargRectilinearGridTest, AxesKeepStoredValuesAndDirections) {
  const InputCatalog c = scan_inputs({kFile}, {});
  // 192 longitudes round the Earth: periodic, the first meridian repeated at 360.
  EXPECT_EQ(c.dims(), (Dims3{193, 96, 17}));
  EXPECT_TRUE(c.x.periodic);

  EXPECT_EQ(c.x.name, "lon");
  EXPECT_EQ(c.x.kind, AxisKind::kLongitude);
  EXPECT_EQ(c.x.units, "degrees_east");
  EXPECT_EQ(c.x.standard_name, "longitude");
  auto lon = read_vara(kFile, "lon", {0}, {192});
  lon.push_back(lon.front() + 360.0);
  EXPECT_EQ(c.x.values, lon);
  EXPECT_FALSE(c.x.descending());

  EXPECT_EQ(c.y.name, "lat");
  EXPECT_EQ(c.y.kind, AxisKind::kLatitude);
  EXPECT_TRUE(c.y.descending());  // north to south, kept as stored
  EXPECT_EQ(c.y.values, read_vara(kFile, "lat", {0}, {96}));
  EXPECT_NEAR(c.y.values.front(), 88.5721685140073, 1e-12);

  EXPECT_EQ(c.z.name, "lev");
  EXPECT_EQ(c.z.kind, AxisKind::kPressure);
  EXPECT_EQ(c.z.units, "Pa");
  EXPECT_EQ(c.z.long_name, "pressure");
  EXPECT_TRUE(c.z.descending());
  EXPECT_EQ(c.z.values.front(), 100000.0);
  EXPECT_EQ(c.z.values.back(), 1000.0);
}

TEST(NcargRectilinearGridTest, TimeAxisAndVariablesInFileOrder) {
  const InputCatalog c = scan_inputs({kFile}, {});
  EXPECT_EQ(c.time.name, "time");
  EXPECT_EQ(c.time.units, "hours since 2001-01-01 00:00:00");
  EXPECT_EQ(c.time.calendar, "standard");
  EXPECT_EQ(c.time.values, std::vector<double>{0.0});
  ASSERT_EQ(c.variables.size(), 3u);
  EXPECT_EQ(c.variables[0].name, "rhumidity");
  EXPECT_EQ(c.variables[1].name, "var3");
  EXPECT_EQ(c.variables[2].name, "t");
  const VariableMeta& t = c.variables[c.variable_index("t")];
  EXPECT_EQ(t.units, "K");
  EXPECT_EQ(t.long_name, "temperature");
  EXPECT_EQ(t.source_type, "float");
  EXPECT_EQ(t.store_type, DType::kFloat32);
  EXPECT_FALSE(t.fill_value.has_value());
  EXPECT_FALSE(t.scale_factor.has_value());
  ASSERT_EQ(c.locations.size(), 3u);
  EXPECT_EQ(c.locations[2].size(), 1u);
  EXPECT_EQ(c.locations[2][0].file, 0u);
  EXPECT_EQ(c.locations[2][0].time_in_file, 0u);
}

TEST(NcargRectilinearGridTest, SourceFileIsAbsoluteWithSizeAndHeaderChecksum) {
  const InputCatalog c = scan_inputs({kFile}, {});
  ASSERT_EQ(c.files.size(), 1u);
  EXPECT_EQ(c.files[0].path, kFile.string());
  EXPECT_EQ(c.files[0].size, std::filesystem::file_size(kFile));
  std::vector<std::byte> head(64 * 1024);
  ReadOnlyFile(kFile).read_at(0, head);
  EXPECT_EQ(c.files[0].header_checksum, checksum64(head));
}

TEST(NcargRectilinearGridTest, SlabReaderReturnsWhatNetcdfReturns) {
  const InputCatalog c = scan_inputs({kFile}, {});
  SlabReader reader(c, {});
  const std::size_t t = c.variable_index("t");
  std::vector<float> slab(2 * 96 * 193);
  reader.read(t, 0, 3, 5, slab);
  const auto expected =
      with_repeated_first_column(read_vara(kFile, "t", {0, 3, 0, 0}, {1, 2, 96, 192}), 192);
  ASSERT_EQ(slab.size(), expected.size());
  for (std::size_t i = 0; i < slab.size(); ++i) {
    ASSERT_EQ(slab[i], static_cast<float>(expected[i])) << "sample " << i;
  }
  // A float variable read into doubles: plain conversion.
  std::vector<double> top(96 * 193);
  reader.read(t, 0, 16, 17, top);
  const auto expected_top =
      with_repeated_first_column(read_vara(kFile, "t", {0, 16, 0, 0}, {1, 1, 96, 192}), 192);
  EXPECT_EQ(top, expected_top);
}

}  // namespace
}  // namespace strielad::ingest
