// SPDX-License-Identifier: Apache-2.0
// The real rotated-pole DEM of a regional model (HSURF in libncarg-data): samples placed
// through the grid mapping (PROJ, as the stores are placed) match PROJ's cs2cs and the
// file's own 2-D lat/lon; heights in a known range; strided reads equal the full read's
// samples.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <cmath>
#include <filesystem>

#include "scenery/dem_source.h"
#include "support/cs2cs.h"

namespace strielad {
namespace {

const std::filesystem::path kHsurf =
    std::filesystem::path(STRIELAD_NCARG_DATA_DIR) / "nug/HSURF_regional_model_0.11deg.nc";

float file_value(const char* var, std::size_t row, std::size_t col) {
  int nc = -1, v = -1;
  EXPECT_EQ(nc_open(kHsurf.c_str(), NC_NOWRITE, &nc), NC_NOERR);
  EXPECT_EQ(nc_inq_varid(nc, var, &v), NC_NOERR);
  int dims = 0;
  EXPECT_EQ(nc_inq_varndims(nc, v, &dims), NC_NOERR);
  // HSURF is (time, rlat, rlon); lat and lon are (rlat, rlon).
  const std::size_t index[3] = {dims == 3 ? 0 : row, dims == 3 ? row : col, col};
  float value = NAN;
  EXPECT_EQ(nc_get_var1_float(nc, v, index, &value), NC_NOERR);
  nc_close(nc);
  return value;
}

// The file's rotated axis value (rlon or rlat) at `index`.
double axis_value(const char* var, std::size_t index) {
  int nc = -1, v = -1;
  EXPECT_EQ(nc_open(kHsurf.c_str(), NC_NOWRITE, &nc), NC_NOERR);
  EXPECT_EQ(nc_inq_varid(nc, var, &v), NC_NOERR);
  double value = NAN;
  EXPECT_EQ(nc_get_var1_double(nc, v, &index, &value), NC_NOERR);
  nc_close(nc);
  return value;
}

TEST(DemRotatedPoleTest, SamplesLieWhereCs2csPutsThem) {
  if (!std::filesystem::exists(kHsurf)) GTEST_SKIP() << kHsurf << " missing (libncarg-data)";
  if (!testing::have_cs2cs()) GTEST_SKIP() << "cs2cs (proj-bin) missing";
  const auto dem = geo::open_dem(kHsurf);
  std::vector<std::pair<std::size_t, std::size_t>> samples;  // (row, col)
  for (std::size_t row = 0; row < 438; row += 73) {
    for (std::size_t col = 0; col < 450; col += 89) samples.emplace_back(row, col);
  }
  samples.emplace_back(437, 449);
  std::vector<std::array<double, 2>> rotated;
  for (const auto& [row, col] : samples) rotated.push_back({axis_value("rlon", col), axis_value("rlat", row)});
  const auto expected = testing::cs2cs(testing::kEuroCordexRotatedPole, "+proj=longlat", rotated);
  ASSERT_TRUE(expected);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const auto ll = dem->georeference(double(samples[i].second), double(samples[i].first));
    EXPECT_NEAR(std::remainder(ll.lon - (*expected)[i][0], 360.0), 0.0, 1e-9) << i;
    EXPECT_NEAR(ll.lat, (*expected)[i][1], 1e-9) << i;
  }
  // The pole's meridian runs through the grid's centre: rotated (0, 0) is 18 E, 50.75 N.
  const auto centre = testing::cs2cs(testing::kEuroCordexRotatedPole, "+proj=longlat", {{0.0, 0.0}});
  ASSERT_TRUE(centre);
  EXPECT_NEAR((*centre)[0][0], 18.0, 1e-9);
  EXPECT_NEAR((*centre)[0][1], 50.75, 1e-9);
}

TEST(DemRotatedPoleTest, SamplesMatchTheFilesLatLon) {
  if (!std::filesystem::exists(kHsurf)) GTEST_SKIP() << kHsurf << " missing (libncarg-data)";
  const auto dem = geo::open_dem(kHsurf);  // HSURF found by standard_name
  ASSERT_EQ(dem->width(), 450u);
  ASSERT_EQ(dem->height(), 438u);
  EXPECT_NE(dem->describe().find("HSURF"), std::string::npos);
  EXPECT_NE(dem->georeferencing().find("rotated_latitude_longitude"), std::string::npos);
  for (const auto& [row, col] : {std::pair<std::size_t, std::size_t>{0, 0}, {0, 449}, {437, 0},
                                 {437, 449}, {219, 225}}) {
    const auto ll = dem->georeference(double(col), double(row));
    EXPECT_NEAR(ll.lon, file_value("lon", row, col), 1e-4) << row << "," << col;
    EXPECT_NEAR(ll.lat, file_value("lat", row, col), 1e-4) << row << "," << col;
  }
}

TEST(DemRotatedPoleTest, HeightsInTheKnownRange) {
  if (!std::filesystem::exists(kHsurf)) GTEST_SKIP();
  const auto dem = geo::open_dem(kHsurf, "HSURF");
  const auto all = dem->read({0, 0, 450, 438, 1});
  float lo = INFINITY, hi = -INFINITY;
  for (const float v : all) {
    ASSERT_FALSE(std::isnan(v));
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  // Europe at 0.11 degrees: -194.5 m to 3,138 m (the Alps and the Caucasus, smoothed).
  EXPECT_GT(lo, -250.0f);  // the Caspian depression: -194.5 m
  EXPECT_LT(lo, 10.0f);
  EXPECT_GT(hi, 2500.0f);
  EXPECT_LT(hi, 4810.0f);
  EXPECT_EQ(all[219 * 450 + 225], file_value("HSURF", 219, 225));
}

TEST(DemRotatedPoleTest, StridedReadEqualsTheFullReadsSamples) {
  if (!std::filesystem::exists(kHsurf)) GTEST_SKIP();
  const auto dem = geo::open_dem(kHsurf);
  const auto all = dem->read({0, 0, 450, 438, 1});
  const geo::DemWindow w{7, 11, 40, 30, 5};
  const auto strided = dem->read(w);
  ASSERT_EQ(strided.size(), 40u * 30u);
  for (std::size_t r = 0; r < w.rows; ++r) {
    for (std::size_t c = 0; c < w.cols; ++c) {
      ASSERT_EQ(strided[r * w.cols + c], all[(w.row0 + r * w.stride) * 450 + w.col0 + c * w.stride]);
    }
  }
}

}  // namespace
}  // namespace strielad
