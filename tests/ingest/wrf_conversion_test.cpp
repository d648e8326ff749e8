// SPDX-License-Identifier: Apache-2.0
// A WRF history file converted end to end: a version-5 store on the Lambert conformal
// mapping whose time-varying height field is, at every sample of every step, the mean of
// the w levels' (PH + PHB) / 9.81 around it (WRF's g, computed here from the file read
// with netCDF), with HGT as the surface; T stored as the potential temperature theta,
// every sample T + 300 K.
#include <gtest/gtest.h>
#include <netcdf.h>

#include <cmath>
#include <vector>

#include "convert/converter.h"
#include "core/error.h"
#include "format/geometry_field.h"
#include "store/level_samples.h"
#include "store/store.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"
#include "synthetic/model_like_files.h"

namespace strielad {
namespace {

constexpr Dims3 kDims{12, 10, 7};

TEST(WrfConversionTest, PhPlusPhbPlaceTheLevelsOfEveryStep) {
  const testing::TempDir dir;
  synthetic::SampleSpec s;
  s.dims = kDims;
  s.steps = 2;
  s.step_seconds = 3600;
  s.file_per_step = false;
  const auto input =
      synthetic::write_model_like_dataset(s, synthetic::SampleModel::kWrf, dir / "in")
          .files[0]
          .path;
  build::ConvertOptions o;
  o.inputs = {input};
  o.store = dir / "store";
  o.brick = 8;
  o.threads = 1;
  build::convert(o);

  const auto store = Store::open(dir / "store");
  const format::Manifest& m = store->manifest();
  EXPECT_EQ(m.format_version, 5u);
  ASSERT_TRUE(m.geometry);
  EXPECT_EQ(m.geometry->vertical.kind, format::VerticalGeometry::Kind::kField);
  EXPECT_EQ(m.geometry->vertical.sources, (std::vector<std::string>{"PH", "PHB"}));
  EXPECT_TRUE(m.geometry->vertical.varies_in_time);
  ASSERT_TRUE(m.geometry->surface);
  EXPECT_EQ(m.geometry->surface->variable, "HGT");

  const std::vector<double> ph = testing::read_netcdf_variable(input, "PH").values,
                            phb = testing::read_netcdf_variable(input, "PHB").values;
  const std::size_t plane = kDims.x * kDims.y, w_levels = kDims.z + 1;
  ASSERT_EQ(ph.size(), 2 * w_levels * plane);
  const auto v = *format::geometry_field_variable(m);
  for (std::uint32_t step = 0; step < 2; ++step) {
    const auto heights = read_level_samples<float>(*store, step, v, 0);
    ASSERT_EQ(heights.values.size(), kDims.z * plane);
    for (std::size_t k = 0; k < kDims.z; ++k) {
      for (std::size_t c = 0; c < plane; ++c) {
        const std::size_t below = (step * w_levels + k) * plane + c, above = below + plane;
        const double want =
            0.5 * ((ph[below] + phb[below]) / 9.81 + (ph[above] + phb[above]) / 9.81);
        // float32 in the store: within an ulp (1.2e-7 relative), which g = 9.80665
        // (3.4e-4 relative) is far outside.
        ASSERT_NEAR(heights.values[k * plane + c], want, 1.2e-7 * std::abs(want))
            << "step " << step << " k " << k << " column " << c;
      }
    }
  }
  // The surface, HGT of the first step, exactly.
  const auto coordinates = store->horizontal_coordinates();
  ASSERT_TRUE(coordinates && coordinates->surface_m);
  const std::vector<double> hgt = testing::read_netcdf_variable(input, "HGT").values;
  EXPECT_EQ(*coordinates->surface_m, std::vector<double>(hgt.begin(), hgt.begin() + plane));

  // T is stored as the potential temperature theta = T + 300 K (float32, as T is).
  EXPECT_THROW(m.variable_index("T"), Error);
  const std::size_t theta = m.variable_index("theta");
  EXPECT_EQ(m.variables[theta].units, "K");
  EXPECT_EQ(m.variables[theta].long_name, "potential temperature (T + 300 K)");
  EXPECT_EQ(m.variables[theta].standard_name, "air_potential_temperature");
  EXPECT_EQ(m.variables[theta].dtype, DType::kFloat32);
  const std::vector<double> t = testing::read_netcdf_variable(input, "T").values;
  ASSERT_EQ(t.size(), 2 * kDims.z * plane);
  for (std::uint32_t step = 0; step < 2; ++step) {
    const auto got = read_level_samples<float>(*store, step, static_cast<std::uint32_t>(theta), 0);
    ASSERT_EQ(got.values.size(), kDims.z * plane);
    for (std::size_t s = 0; s < got.values.size(); ++s) {
      ASSERT_EQ(got.values[s], static_cast<float>(t[step * kDims.z * plane + s] + 300.0))
          << "step " << step << " sample " << s;
    }
  }
}

}  // namespace
}  // namespace strielad
