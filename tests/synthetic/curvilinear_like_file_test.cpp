// SPDX-License-Identifier: Apache-2.0
// The curvilinear sample (--model curvilinear) read back with netCDF: a rotated-pole grid
// written only as 2-D lat(y, x), lon(y, x) — no grid_mapping, no rlon/rlat, no
// coordinate variables for y and x — whose positions are PROJ's for the pole at 40 N,
// 170 W, and five variables on height levels that name them in `coordinates`.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <cmath>
#include <string>

#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"
#include "synthetic/curvilinear_like_file.h"
#include "synthetic/model_like_files.h"
#include "synthetic/sample_args.h"

namespace strielad::testing {
namespace {

using synthetic::SampleModel;

constexpr Dims3 kDims{20, 16, 5};

TEST(CurvilinearLikeFileTest, ModelNameParses) {
  EXPECT_EQ(synthetic::parse_sample_model("curvilinear"), SampleModel::kCurvilinear);
  EXPECT_EQ(synthetic::sample_model_name(SampleModel::kCurvilinear), "curvilinear");
  EXPECT_EQ(synthetic::model_sample_variable_names(SampleModel::kCurvilinear),
            (std::vector<std::string>{"temp", "qc", "u", "v", "w"}));
}

TEST(CurvilinearLikeFileTest, OnlyTwoDimensionalCoordinatesPlaceTheGrid) {
  const TempDir dir;
  synthetic::SampleSpec spec;
  spec.dims = kDims;
  spec.steps = 2;
  spec.file_per_step = false;
  const auto result = synthetic::write_model_like_dataset(spec, SampleModel::kCurvilinear, dir.path());
  ASSERT_EQ(result.files.size(), 1u);
  const auto path = result.files[0].path;
  EXPECT_EQ(path.filename(), "curvilinear.nc");

  int ncid = -1;
  ASSERT_EQ(nc_open(path.c_str(), NC_NOWRITE, &ncid), NC_NOERR);
  int varid = -1;
  for (const char* absent : {"rlon", "rlat", "x", "y", "rotated_pole", "crs"}) {
    EXPECT_NE(nc_inq_varid(ncid, absent, &varid), NC_NOERR) << absent;
  }
  for (const char* name : {"temp", "qc", "u", "v", "w"}) {
    ASSERT_EQ(nc_inq_varid(ncid, name, &varid), NC_NOERR) << name;
    EXPECT_EQ(nc_inq_att(ncid, varid, "grid_mapping", nullptr, nullptr), NC_ENOTATT) << name;
    char coordinates[32] = {};
    ASSERT_EQ(nc_get_att_text(ncid, varid, "coordinates", coordinates), NC_NOERR);
    EXPECT_EQ(std::string(coordinates), "lon lat");
  }
  nc_close(ncid);

  const NetcdfValues lon = read_netcdf_variable(path, "lon"), lat = read_netcdf_variable(path, "lat");
  EXPECT_EQ(lon.shape, (std::vector<std::size_t>{kDims.y, kDims.x}));
  const synthetic::CurvilinearSampleGrid grid = synthetic::curvilinear_sample_grid(kDims.x, kDims.y);
  EXPECT_EQ(lon.values, grid.lon);
  EXPECT_EQ(lat.values, grid.lat);
  // The grid spans rlon -4.5 .. 4.5, rlat -3 .. 4 around the rotated origin at 10 E, 50 N
  // (pole 40 N, 170 W), over Germany.
  EXPECT_EQ(synthetic::curvilinear_sample_proj_string(),
            "+proj=ob_tran +o_proj=longlat +o_lat_p=40 +o_lon_p=0 +lon_0=10");
  for (std::size_t k = 0; k < lon.values.size(); ++k) {
    EXPECT_GT(lon.values[k], 2.0);
    EXPECT_LT(lon.values[k], 18.0);
    EXPECT_GT(lat.values[k], 46.0);
    EXPECT_LT(lat.values[k], 55.0);
  }
}

}  // namespace
}  // namespace strielad::testing
