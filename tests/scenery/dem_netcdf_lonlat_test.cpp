// SPDX-License-Identifier: Apache-2.0
// NetCDF DEMs on regular lon/lat axes written by the test: a descending latitude axis,
// _FillValue -> NaN, km units; and the errors that name the file and variable.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <cmath>
#include <fstream>
#include <vector>

#include "scenery/dem_source.h"
#include "support/expect_error.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using testing::expect_error;

// elevation(lat, lon): 5 x 4, latitude 54 down to 50, longitude 6..9; value 100 * row + col,
// with the sample (row 2, col 1) the fill value. Optionally a 3-D variable "t3" (2 x 5 x 4).
std::filesystem::path write_lonlat_dem(const std::filesystem::path& dir, const char* units = "m") {
  const auto path = dir / "dem.nc";
  int nc = -1, dlat = 0, dlon = 0, dz = 0, vlat = 0, vlon = 0, vh = 0, v3 = 0;
  EXPECT_EQ(nc_create(path.c_str(), NC_CLOBBER | NC_NETCDF4, &nc), NC_NOERR);
  nc_def_dim(nc, "lat", 5, &dlat);
  nc_def_dim(nc, "lon", 4, &dlon);
  nc_def_dim(nc, "level", 2, &dz);
  nc_def_var(nc, "lat", NC_DOUBLE, 1, &dlat, &vlat);
  nc_put_att_text(nc, vlat, "units", 13, "degrees_north");
  nc_def_var(nc, "lon", NC_DOUBLE, 1, &dlon, &vlon);
  nc_put_att_text(nc, vlon, "units", 12, "degrees_east");
  const int dims[2] = {dlat, dlon};
  nc_def_var(nc, "elevation", NC_FLOAT, 2, dims, &vh);
  nc_put_att_text(nc, vh, "units", std::strlen(units), units);
  const float fill = -32768.0f;
  nc_put_att_float(nc, vh, "_FillValue", NC_FLOAT, 1, &fill);
  const int dims3[3] = {dz, dlat, dlon};
  nc_def_var(nc, "t3", NC_FLOAT, 3, dims3, &v3);
  nc_enddef(nc);
  const double lat[5] = {54, 53, 52, 51, 50}, lon[4] = {6, 7, 8, 9};
  nc_put_var_double(nc, vlat, lat);
  nc_put_var_double(nc, vlon, lon);
  std::vector<float> h(20);
  for (int r = 0; r < 5; ++r) {
    for (int c = 0; c < 4; ++c) h[r * 4 + c] = float(100 * r + c);
  }
  h[2 * 4 + 1] = fill;
  nc_put_var_float(nc, vh, h.data());
  std::vector<float> t(40, 1.0f);
  nc_put_var_float(nc, v3, t.data());
  nc_close(nc);
  return path;
}

TEST(DemNetcdfLonLatTest, DescendingLatitudeAndFill) {
  testing::TempDir dir;
  const auto dem = geo::open_dem(write_lonlat_dem(dir.path()));  // "elevation" by name
  ASSERT_EQ(dem->width(), 4u);
  ASSERT_EQ(dem->height(), 5u);
  const auto first = dem->georeference(0, 0);
  EXPECT_DOUBLE_EQ(first.lon, 6.0);
  EXPECT_DOUBLE_EQ(first.lat, 54.0);  // row 0 is the north
  const auto last = dem->georeference(3, 4);
  EXPECT_DOUBLE_EQ(last.lon, 9.0);
  EXPECT_DOUBLE_EQ(last.lat, 50.0);
  EXPECT_DOUBLE_EQ(dem->georeference(1.5, 2.5).lat, 51.5);  // fractional positions
  const auto h = dem->read({0, 0, 4, 5, 1});
  EXPECT_EQ(h[0], 0.0f);
  EXPECT_EQ(h[4 * 4 + 3], 403.0f);
  EXPECT_TRUE(std::isnan(h[2 * 4 + 1]));
  const auto strided = dem->read({1, 0, 2, 3, 2});  // cols 1, 3; rows 0, 2, 4
  ASSERT_EQ(strided.size(), 6u);
  EXPECT_EQ(strided[0], 1.0f);
  EXPECT_EQ(strided[1], 3.0f);
  EXPECT_TRUE(std::isnan(strided[2]));
  EXPECT_EQ(strided[5], 403.0f);
}

TEST(DemNetcdfLonLatTest, KilometresBecomeMetres) {
  testing::TempDir dir;
  const auto dem = geo::open_dem(write_lonlat_dem(dir.path(), "km"), "elevation");
  EXPECT_EQ(dem->read({3, 4, 1, 1, 1})[0], 403000.0f);
}

TEST(DemNetcdfLonLatTest, MissingVariable) {
  testing::TempDir dir;
  const auto path = write_lonlat_dem(dir.path());
  expect_error([&] { geo::open_dem(path, "HSURF"); }, ErrorCode::kNotFound,
               {path.string(), "'HSURF'", "elevation"});
}

TEST(DemNetcdfLonLatTest, ThreeDimensionalVariable) {
  testing::TempDir dir;
  const auto path = write_lonlat_dem(dir.path());
  expect_error([&] { geo::open_dem(path, "t3"); }, ErrorCode::kInvalidInput,
               {path.string(), "t3", "level=2", "2-D"});
}

TEST(DemNetcdfLonLatTest, NotARaster) {
  testing::TempDir dir;
  const auto path = dir.path() / "notes.txt";
  std::ofstream(path) << "this is not a raster\n";
  expect_error([&] { geo::open_dem(path); }, ErrorCode::kInvalidInput, {path.string(), "raster"});
  expect_error([&] { geo::open_dem(dir.path() / "absent.nc"); }, ErrorCode::kNotFound,
               {"absent.nc"});
}

TEST(DemNetcdfLonLatTest, WindowOutsideTheGrid) {
  testing::TempDir dir;
  const auto dem = geo::open_dem(write_lonlat_dem(dir.path()));
  expect_error([&] { dem->read({0, 0, 3, 1, 2}); }, ErrorCode::kInvalidArgument, {"outside"});
}

}  // namespace
}  // namespace strielad
