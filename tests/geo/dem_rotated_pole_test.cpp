// SPDX-License-Identifier: Apache-2.0
// The real rotated-pole DEM of a regional model (HSURF in libncarg-data): samples placed
// by the pole formula match the file's own 2-D lat/lon; heights in a known range;
// strided reads equal the full read's samples.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <cmath>
#include <filesystem>

#include "geo/dem_source.h"
#include "geo/rotated_pole.h"

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

TEST(RotatedPoleTest, RoundTripAndCentre) {
  const geo::RotatedPole pole{39.25, -162.0, 0.0};
  const auto centre = geo::rotated_to_geographic(pole, 0, 0);
  EXPECT_NEAR(centre.lon, 18.0, 1e-12);
  EXPECT_NEAR(centre.lat, 50.75, 1e-12);
  for (double rlon = -20; rlon <= 20; rlon += 5) {
    for (double rlat = -20; rlat <= 20; rlat += 5) {
      const auto g = geo::rotated_to_geographic(pole, rlon, rlat);
      const auto r = geo::geographic_to_rotated(pole, g.lon, g.lat);
      EXPECT_NEAR(r.lon, rlon, 1e-9);
      EXPECT_NEAR(r.lat, rlat, 1e-9);
    }
  }
}

TEST(DemRotatedPoleTest, SamplesMatchTheFilesLatLon) {
  if (!std::filesystem::exists(kHsurf)) GTEST_SKIP() << kHsurf << " missing (libncarg-data)";
  const auto dem = geo::open_dem(kHsurf);  // HSURF found by standard_name
  ASSERT_EQ(dem->width(), 450u);
  ASSERT_EQ(dem->height(), 438u);
  EXPECT_NE(dem->describe().find("HSURF"), std::string::npos);
  EXPECT_NE(dem->georeferencing().find("rotated pole"), std::string::npos);
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
