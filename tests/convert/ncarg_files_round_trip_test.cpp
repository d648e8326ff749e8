// SPDX-License-Identifier: Apache-2.0
// Real model output no one here wrote (Debian package libncarg-data) converts and its
// level 0 equals what netCDF itself returns, fill positions included.
#include <gtest/gtest.h>

#include <cmath>

#include "convert/converter.h"
#include "store/store.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

struct RealFile {
  const char* path;
  const char* variable;  // name in the store
  const char* nc_name;   // name for nc_get_vara ("grp/var" for groups)
  double fill;           // the file's _FillValue (NaN when none)
  double valid_min, valid_max;  // valid_range (infinite when none)
  bool expect_fills;     // the data really holds missing samples
};

class NcargFilesRoundTripTest : public ::testing::TestWithParam<RealFile> {};

TEST_P(NcargFilesRoundTripTest, LevelZeroEqualsNetcdfValues) {
  const RealFile f = GetParam();
  const auto input = testing::ncarg_file(f.path);
  if (!std::filesystem::exists(input)) GTEST_SKIP() << "libncarg-data not installed";
  testing::TempDir dir;
  build::ConvertOptions o;
  o.inputs = {input};
  o.store = dir / "store";
  o.scan.variables = {f.variable};
  o.brick = 8;
  const auto r = build::convert(o);
  ASSERT_TRUE(r.finalized);
  const auto store = Store::open(o.store);
  const Dims3 g = store->octree().grid();
  const std::uint32_t steps = static_cast<std::uint32_t>(store->step_count());
  std::size_t fills = 0;
  // A periodic longitude axis holds the first meridian once more at the end (none of these
  // files repeats it itself).
  const std::size_t file_nx = store->manifest().x.periodic && g.x > 1 ? g.x - 1 : g.x;
  for (std::uint32_t t = 0; t < steps; ++t) {
    const std::vector<std::size_t> start{t, 0, 0, 0}, count{1, g.z, g.y, file_nx};
    auto expected = testing::read_vara(input, f.nc_name, start, count);
    if (file_nx != g.x) expected = testing::with_repeated_first_column(expected, file_nx);
    for (NodeId n = 0; n < store->octree().level(0).node_count(); ++n) {
      const Brick b = store->read_brick(t, 0, n);
      for (std::size_t z = 0; z < b.dims[2]; ++z)
        for (std::size_t y = 0; y < b.dims[1]; ++y)
          for (std::size_t x = 0; x < b.dims[0]; ++x) {
            const double got = b.sample((z * b.dims[1] + y) * b.dims[0] + x);
            const double want =
                expected[((b.box.lo[2] + z) * g.y + b.box.lo[1] + y) * g.x + b.box.lo[0] + x];
            if (want == f.fill || want < f.valid_min || want > f.valid_max) {
              ++fills;
              ASSERT_TRUE(std::isnan(got)) << f.path << " node " << n;
            } else {
              ASSERT_EQ(got, static_cast<double>(static_cast<float>(want))) << f.path << " node " << n;
            }
          }
    }
  }
  if (f.expect_fills) {
    EXPECT_GT(fills, 0u) << f.path << " has missing values that must survive";
  }
}

INSTANTIATE_TEST_SUITE_P(
    RealFiles, NcargFilesRoundTripTest,
    ::testing::Values(
        RealFile{"nug/rectilinear_grid_3D.nc", "t", "t", NAN, -INFINITY, INFINITY, false},
        RealFile{"cdf/contour.cdf", "T", "T", -9999.0, 0.0, 400.0, false},
        RealFile{"cdf/contour.cdf", "Z", "Z", -9999.0, -150.0, 5000.0, true},
        RealFile{"cdf/nc4uvt.nc", "T", "T", -999.0, -INFINITY, INFINITY, false},
        RealFile{"cdf/nc4uvt.nc", "grp1/T", "grp1/T", -999.0, -INFINITY, INFINITY, false}),
    [](const auto& info) {
      std::string name = std::string(info.param.path) + "_" + info.param.variable;
      for (char& c : name) {
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      }
      return name;
    });

}  // namespace
}  // namespace strielad
