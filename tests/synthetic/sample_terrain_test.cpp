// SPDX-License-Identifier: Apache-2.0
// The sample DEM (lib/synthetic/sample_terrain.h) is written on the regional models'
// rotated pole: its own 2-D longitude/latitude agree with PROJ's cs2cs, its samples cover
// the sample domain (4.5-14.5 E, 47.5-54.5 N), and the DEM reader places them there.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <cmath>

#include "scenery/dem_source.h"
#include "synthetic/sample_terrain.h"
#include "support/cs2cs.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

std::vector<double> read_all(int nc, const char* name) {
  int v = -1, dims[2] = {};
  int nd = 0;
  EXPECT_EQ(nc_inq_varid(nc, name, &v), NC_NOERR);
  EXPECT_EQ(nc_inq_varndims(nc, v, &nd), NC_NOERR);
  EXPECT_EQ(nc_inq_vardimid(nc, v, dims), NC_NOERR);
  std::size_t n = 1;
  for (int d = 0; d < nd; ++d) {
    std::size_t len = 0;
    EXPECT_EQ(nc_inq_dimlen(nc, dims[d], &len), NC_NOERR);
    n *= len;
  }
  std::vector<double> out(n);
  EXPECT_EQ(nc_get_var_double(nc, v, out.data()), NC_NOERR);
  return out;
}

TEST(SampleTerrainTest, RotatedPoleAgreesWithCs2csAndCoversTheSampleDomain) {
  if (!testing::have_cs2cs()) GTEST_SKIP() << "cs2cs (proj-bin) missing";
  testing::TempDir dir;
  const auto path = dir / "terrain.nc";
  constexpr std::size_t kN = 33;
  synthetic::write_sample_terrain({.samples = kN, .seed = 7}, path);
  int nc = -1;
  ASSERT_EQ(nc_open(path.c_str(), NC_NOWRITE, &nc), NC_NOERR);
  const auto rlon = read_all(nc, "rlon"), rlat = read_all(nc, "rlat");
  const auto lon = read_all(nc, "lon"), lat = read_all(nc, "lat");
  nc_close(nc);
  ASSERT_EQ(rlon.size(), kN);
  std::vector<std::array<double, 2>> rotated;
  for (std::size_t j = 0; j < kN; ++j) {
    for (std::size_t i = 0; i < kN; ++i) rotated.push_back({rlon[i], rlat[j]});
  }
  const auto expected = testing::cs2cs(testing::kEuroCordexRotatedPole, "+proj=longlat", rotated);
  ASSERT_TRUE(expected);
  double lon_lo = INFINITY, lon_hi = -INFINITY, lat_lo = INFINITY, lat_hi = -INFINITY;
  const auto dem = geo::open_dem(path);
  for (std::size_t k = 0; k < rotated.size(); ++k) {
    EXPECT_NEAR(lon[k], (*expected)[k][0], 2e-5) << k;  // float in the file
    EXPECT_NEAR(lat[k], (*expected)[k][1], 2e-5) << k;
    const auto ll = dem->georeference(double(k % kN), double(k / kN));
    EXPECT_NEAR(ll.lon, (*expected)[k][0], 1e-9) << k;
    EXPECT_NEAR(ll.lat, (*expected)[k][1], 1e-9) << k;
    lon_lo = std::min(lon_lo, lon[k]);
    lon_hi = std::max(lon_hi, lon[k]);
    lat_lo = std::min(lat_lo, lat[k]);
    lat_hi = std::max(lat_hi, lat[k]);
  }
  EXPECT_LT(lon_lo, 4.5);
  EXPECT_GT(lon_hi, 14.5);
  EXPECT_LT(lat_lo, 47.5);
  EXPECT_GT(lat_hi, 54.5);
}

}  // namespace
}  // namespace strielad
