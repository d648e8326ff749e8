// SPDX-License-Identifier: Apache-2.0
// The files are CF-1.8 NetCDF-4: coordinate and variable attributes, layout
// var(time, height, lat, lon), one level per chunk, optional deflate with shuffle.
#include <gtest/gtest.h>

#include <map>

#include "sample_test_util.h"

namespace strielad::testing {
namespace {

class SampleCfAttributesTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    auto spec = small_spec(Dims3{12, 10, 6});
    spec.deflate = 4;
    sample_ = new GeneratedSample(spec);
  }
  static void TearDownTestSuite() {
    delete sample_;
    sample_ = nullptr;
  }
  static GeneratedSample* sample_;
};
GeneratedSample* SampleCfAttributesTest::sample_ = nullptr;

TEST_F(SampleCfAttributesTest, FileIsNetcdf4WithGlobalAttributes) {
  const NcFile f(sample_->file());
  int format = 0;
  ASSERT_EQ(nc_inq_format(f.id(), &format), NC_NOERR);
  EXPECT_EQ(format, NC_FORMAT_NETCDF4);
  EXPECT_EQ(f.text_att("", "Conventions"), "CF-1.8");
  EXPECT_EQ(f.text_att("", "source"), "strielad-sample");
  EXPECT_FALSE(f.text_att("", "title").empty());
  EXPECT_TRUE(f.has_att("", "seed"));
}

TEST_F(SampleCfAttributesTest, CoordinatesCarryCfAttributes) {
  const NcFile f(sample_->file());
  EXPECT_EQ(f.text_att("lon", "axis"), "X");
  EXPECT_EQ(f.text_att("lon", "standard_name"), "longitude");
  EXPECT_EQ(f.text_att("lon", "units"), "degrees_east");
  EXPECT_EQ(f.text_att("lat", "axis"), "Y");
  EXPECT_EQ(f.text_att("lat", "standard_name"), "latitude");
  EXPECT_EQ(f.text_att("lat", "units"), "degrees_north");
  EXPECT_EQ(f.text_att("height", "axis"), "Z");
  EXPECT_EQ(f.text_att("height", "standard_name"), "height");
  EXPECT_EQ(f.text_att("height", "units"), "m");
  EXPECT_EQ(f.text_att("height", "positive"), "up");
  EXPECT_EQ(f.text_att("time", "axis"), "T");
  EXPECT_EQ(f.text_att("time", "standard_name"), "time");
  EXPECT_EQ(f.text_att("time", "units"), "seconds since 2013-04-26 12:00:00");
  EXPECT_EQ(f.text_att("time", "calendar"), "proleptic_gregorian");
  for (const char* c : {"lon", "lat", "height", "time"}) {
    EXPECT_FALSE(f.text_att(c, "long_name").empty()) << c;
  }
  // time is the unlimited (record) dimension.
  int unlimited = -1, time_dim = -2;
  ASSERT_EQ(nc_inq_unlimdim(f.id(), &unlimited), NC_NOERR);
  ASSERT_EQ(nc_inq_dimid(f.id(), "time", &time_dim), NC_NOERR);
  EXPECT_EQ(unlimited, time_dim);
}

TEST_F(SampleCfAttributesTest, VariablesCarryUnitsNamesAndFillValue) {
  const NcFile f(sample_->file());
  const std::map<std::string, std::pair<std::string, std::string>> expected{
      {"clw", {"kg kg-1", "mass_fraction_of_cloud_liquid_water_in_air"}},
      {"cli", {"kg kg-1", "mass_fraction_of_cloud_ice_in_air"}},
      {"qr", {"kg kg-1", "mass_fraction_of_rain_in_air"}},
      {"ta", {"K", "air_temperature"}},
      {"pres", {"Pa", "air_pressure"}},
      {"ua", {"m s-1", "eastward_wind"}},
      {"va", {"m s-1", "northward_wind"}},
      {"wa", {"m s-1", "upward_air_velocity"}},
  };
  for (const auto& [name, units_std] : expected) {
    ASSERT_TRUE(f.has_var(name)) << name;
    EXPECT_EQ(f.text_att(name, "units"), units_std.first) << name;
    EXPECT_EQ(f.text_att(name, "standard_name"), units_std.second) << name;
    EXPECT_FALSE(f.text_att(name, "long_name").empty()) << name;
    EXPECT_EQ(f.dim_names(name), (std::vector<std::string>{"time", "height", "lat", "lon"}))
        << name;
    const int v = f.varid(name);
    nc_type type = NC_NAT;
    ASSERT_EQ(nc_inq_vartype(f.id(), v, &type), NC_NOERR);
    EXPECT_EQ(type, NC_FLOAT) << name;
    float fill = 0;
    nc_type fill_type = NC_NAT;
    ASSERT_EQ(nc_inq_atttype(f.id(), v, "_FillValue", &fill_type), NC_NOERR) << name;
    EXPECT_EQ(fill_type, NC_FLOAT);
    ASSERT_EQ(nc_get_att_float(f.id(), v, "_FillValue", &fill), NC_NOERR);
    EXPECT_FLOAT_EQ(fill, -9.0e33f);
    for (const float x : f.floats(name)) ASSERT_NE(x, fill) << name;
  }
}

TEST_F(SampleCfAttributesTest, OneLevelPerChunkWithDeflateAndShuffle) {
  const NcFile f(sample_->file());
  const int v = f.varid("clw");
  int storage = -1;
  std::size_t chunks[4] = {};
  ASSERT_EQ(nc_inq_var_chunking(f.id(), v, &storage, chunks), NC_NOERR);
  EXPECT_EQ(storage, NC_CHUNKED);
  EXPECT_EQ(chunks[0], 1u);
  EXPECT_EQ(chunks[1], 1u);
  EXPECT_EQ(chunks[2], 10u);
  EXPECT_EQ(chunks[3], 12u);
  int shuffle = 0, deflate = 0, level = 0;
  ASSERT_EQ(nc_inq_var_deflate(f.id(), v, &shuffle, &deflate, &level), NC_NOERR);
  EXPECT_EQ(shuffle, 1);
  EXPECT_EQ(deflate, 1);
  EXPECT_EQ(level, 4);
}

TEST(SampleCfAttributesNoDeflateTest, DeflateZeroWritesUncompressedChunks) {
  auto spec = small_spec(Dims3{6, 5, 3});
  spec.variables = {"ta"};
  const GeneratedSample s(spec);
  const NcFile f(s.file());
  int shuffle = -1, deflate = -1, level = -1;
  ASSERT_EQ(nc_inq_var_deflate(f.id(), f.varid("ta"), &shuffle, &deflate, &level), NC_NOERR);
  EXPECT_EQ(shuffle, 0);
  EXPECT_EQ(deflate, 0);
  EXPECT_FALSE(f.has_var("clw")) << "only the requested variables are written";
}

}  // namespace
}  // namespace strielad::testing
