// SPDX-License-Identifier: Apache-2.0
// A conversion of GRIB and netCDF inputs together: NCEP's AWIPS 211 forecast
// (libncarg-data) with its temperature written as CF-NetCDF on the same grid and time
// gives a store holding the GRIB variables and the netCDF one, sample for sample what a
// conversion of the GRIB file alone gives.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>

#include "convert/converter.h"
#include "store/level_samples.h"
#include "store/store.h"
#include "support/grib_as_netcdf.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using strielad::testing::ncarg_file;

build::ConvertOptions options(std::vector<std::filesystem::path> inputs,
                              const std::filesystem::path& store) {
  build::ConvertOptions o;
  o.inputs = std::move(inputs);
  o.store = store;
  o.brick = 16;
  o.threads = 1;
  return o;
}

void expect_same_level0(const Store& got, const std::string& got_name, const Store& want,
                        const std::string& want_name) {
  const auto a = read_level_samples<float>(
      got, 0, static_cast<std::uint32_t>(got.manifest().variable_index(got_name)), 0);
  const auto b = read_level_samples<float>(
      want, 0, static_cast<std::uint32_t>(want.manifest().variable_index(want_name)), 0);
  ASSERT_EQ(a.dims, b.dims);
  ASSERT_EQ(a.values.size(), 93u * 65u * 19u);
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    ASSERT_EQ(a.values[i], b.values[i]) << got_name << " sample " << i;
  }
}

TEST(GribNetcdfMixedConversionTest, StoreHoldsBothFormatsVariablesAsTheGribAloneGives) {
  const testing::TempDir dir;
  const auto grib = ncarg_file("grb/fh.0012_tl.press_gr.awp211.grb2");
  testing::GribAsNetcdf spec;
  spec.name = "tmp";
  testing::write_grib_variable_as_netcdf(grib, spec, dir / "tmp.nc");

  auto mixed = options({grib, dir / "tmp.nc"}, dir / "mixed");
  mixed.scan.variables = {"gh", "tmp", "r"};
  build::convert(mixed);
  auto alone = options({grib}, dir / "alone");
  alone.scan.variables = {"gh", "t", "r"};
  build::convert(alone);

  const auto got = Store::open(dir / "mixed");
  const auto want = Store::open(dir / "alone");
  const auto& m = got->manifest();
  ASSERT_EQ(m.variables.size(), 3u);
  EXPECT_EQ(m.variables[0].name, "gh");
  EXPECT_EQ(m.variables[1].name, "tmp");  // in the order asked for
  EXPECT_EQ(m.variables[2].name, "r");
  EXPECT_EQ(m.sources.size(), 2u);
  EXPECT_EQ(m.grid_mapping, want->manifest().grid_mapping);
  EXPECT_EQ(m.time, want->manifest().time);
  EXPECT_EQ(m.x.values, want->manifest().x.values);
  EXPECT_EQ(m.y.values, want->manifest().y.values);
  EXPECT_EQ(m.z.values, want->manifest().z.values);
  expect_same_level0(*got, "gh", *want, "gh");
  expect_same_level0(*got, "r", *want, "r");
  expect_same_level0(*got, "tmp", *want, "t");
}

}  // namespace
}  // namespace strielad
