// SPDX-License-Identifier: Apache-2.0
// The GRIB2 sample (strielad-sample --format grib2) converts to a store whose level-0
// samples are the NetCDF sample's: exactly with IEEE float32 packing, within half a
// packing step with 16-bit simple packing, on the same axes and times; missing samples
// stay missing; a grid that is not regular is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "convert/converter.h"
#include "store/level_samples.h"
#include "store/store.h"
#include "support/expect_error.h"
#include "support/temp_dir.h"
#include "synthetic/grib_sample_writer.h"
#include "synthetic/sample_dataset.h"
#include "synthetic/sample_writer.h"

namespace strielad {
namespace {

constexpr double kSampleEpoch = 1366977600.0;  // 2013-04-26 12:00:00 UTC in Unix seconds

build::ConvertOptions convert_options(std::vector<std::filesystem::path> inputs,
                                      const std::filesystem::path& store) {
  build::ConvertOptions o;
  o.inputs = std::move(inputs);
  o.store = store;
  o.brick = 8;
  o.threads = 1;
  return o;
}

std::vector<std::filesystem::path> paths_of(const synthetic::SampleResult& r) {
  std::vector<std::filesystem::path> out;
  for (const auto& f : r.files) out.push_back(f.path);
  return out;
}

// For every index of `from`, the index of the equal value (within tol) in `to`.
std::vector<std::size_t> axis_map(const Axis& from, const Axis& to, double tol) {
  EXPECT_EQ(from.values.size(), to.values.size()) << from.name << " / " << to.name;
  std::vector<std::size_t> map(from.values.size(), 0);
  for (std::size_t i = 0; i < from.values.size(); ++i) {
    const auto it = std::find_if(to.values.begin(), to.values.end(),
                                 [&](double v) { return std::abs(v - from.values[i]) <= tol; });
    EXPECT_NE(it, to.values.end()) << from.name << " value " << from.values[i] << " not in "
                                   << to.name;
    if (it != to.values.end()) map[i] = static_cast<std::size_t>(it - to.values.begin());
  }
  return map;
}

// Compares every variable and step of the NetCDF store `nc` with the GRIB store `gb`;
// `bits` 0: exactly, else within half a packing step of the level's range.
void expect_same_samples(const Store& nc, const Store& gb, int bits) {
  const auto& mn = nc.manifest();
  const auto& mg = gb.manifest();
  for (const auto& [a, b] : {std::pair{&mn.x, &mg.x}, std::pair{&mn.y, &mg.y}}) {
    ASSERT_EQ(a->values.size(), b->values.size()) << a->name;
    for (std::size_t i = 0; i < a->values.size(); ++i) {
      EXPECT_NEAR(a->values[i], b->values[i], 1e-9) << a->name << " " << i;
    }
  }
  const std::vector<std::size_t> zmap = axis_map(mn.z, mg.z, 1e-3);
  EXPECT_EQ(mg.z.units, "m");
  ASSERT_EQ(mn.time.size(), mg.time.size());
  EXPECT_EQ(mn.time.units, "seconds since 2013-04-26 12:00:00");
  EXPECT_EQ(mg.time.units, "seconds since 1970-01-01 00:00:00");
  for (std::size_t t = 0; t < mn.time.size(); ++t) {
    EXPECT_EQ(mg.time.values[t], kSampleEpoch + mn.time.values[t]) << "step " << t;
  }
  ASSERT_EQ(mn.variables.size(), mg.variables.size());
  for (std::size_t v = 0; v < mn.variables.size(); ++v) {
    const auto variable = synthetic::sample_variable_from_name(mn.variables[v].name);
    const std::string grib_name(synthetic::grib_parameter(variable).short_name);
    const auto gv = static_cast<std::uint32_t>(mg.variable_index(grib_name));
    for (std::uint32_t t = 0; t < mn.time.size(); ++t) {
      const auto a = read_level_samples<float>(nc, t, static_cast<std::uint32_t>(v), 0);
      const auto b = read_level_samples<float>(gb, t, gv, 0);
      ASSERT_EQ(a.dims, b.dims);
      const std::size_t plane = a.dims[0] * a.dims[1];
      for (std::size_t k = 0; k < a.dims[2]; ++k) {
        const float* pa = a.values.data() + k * plane;
        const float* pb = b.values.data() + zmap[k] * plane;
        const auto [lo, hi] = std::minmax_element(pa, pa + plane);
        const double tol =
            bits == 0 ? 0.0
                      : (static_cast<double>(*hi) - static_cast<double>(*lo)) /
                                std::ldexp(1.0, bits) +
                            4 * std::numeric_limits<float>::epsilon() *
                                std::max(std::abs(*hi), std::abs(*lo));
        for (std::size_t i = 0; i < plane; ++i) {
          ASSERT_LE(std::abs(static_cast<double>(pa[i]) - static_cast<double>(pb[i])), tol)
              << grib_name << " step " << t << " level " << k << " sample " << i << ": "
              << pa[i] << " vs " << pb[i];
        }
      }
    }
  }
}

void convert_and_compare(int bits, bool file_per_step) {
  const testing::TempDir dir;
  synthetic::SampleSpec spec;
  spec.dims = {9, 8, 6};
  spec.steps = 2;
  spec.file_per_step = file_per_step;
  const auto netcdf = synthetic::write_sample_dataset(spec, dir / "nc");
  spec.format = synthetic::SampleFormat::kGrib2;
  spec.grib_bits = bits;
  const auto grib = synthetic::write_sample_dataset(spec, dir / "grib");
  ASSERT_EQ(grib.files.size(), file_per_step ? 2u : 1u);
  EXPECT_EQ(grib.files.front().path.extension(), ".grib2");
  build::convert(convert_options(paths_of(netcdf), dir / "nc.store"));
  build::convert(convert_options(paths_of(grib), dir / "grib.store"));
  expect_same_samples(*Store::open(dir / "nc.store"), *Store::open(dir / "grib.store"), bits);
}

TEST(GribSampleTest, IeeeFloatGribConvertsToTheNetcdfSamplesExactly) {
  convert_and_compare(0, true);
}

TEST(GribSampleTest, SixteenBitGribIsWithinThePackingPrecision) {
  convert_and_compare(16, false);
}

TEST(GribSampleTest, MissingSamplesStayMissing) {
  const testing::TempDir dir;
  const synthetic::SampleGrid grid({5, 4, 2});
  std::vector<float> level(grid.level_size());
  const std::vector<synthetic::SampleVariable> vars{synthetic::SampleVariable::kTa};
  synthetic::SampleFileWriter nc(dir / "m.nc", grid, {vars, {0.0}, 1, 0});
  synthetic::GribSampleFileWriter gb(dir / "m.grib2", grid, {vars, {0.0}, 0});
  for (std::size_t k = 0; k < 2; ++k) {
    for (std::size_t i = 0; i < level.size(); ++i) level[i] = 250.0f + static_cast<float>(i + k);
    level[3 + k] = synthetic::kSampleFillValue;
    level[7] = synthetic::kSampleFillValue;
    nc.write_level(0, 0, k, level);
    level[7] = std::numeric_limits<float>::quiet_NaN();  // GRIB: NaN is missing too
    gb.write_level(0, 0, k, level);
  }
  nc.commit();
  gb.commit();
  build::convert(convert_options({dir / "m.nc"}, dir / "nc.store"));
  build::convert(convert_options({dir / "m.grib2"}, dir / "grib.store"));
  const auto a_store = Store::open(dir / "nc.store");
  const auto b_store = Store::open(dir / "grib.store");
  const auto a = read_level_samples<float>(*a_store, 0, 0, 0);
  const auto b = read_level_samples<float>(*b_store, 0, 0, 0);
  const std::vector<std::size_t> zmap = axis_map(a_store->manifest().z, b_store->manifest().z, 1e-3);
  const std::size_t plane = grid.level_size();
  std::size_t missing = 0;
  for (std::size_t k = 0; k < 2; ++k) {
    for (std::size_t i = 0; i < plane; ++i) {
      const float va = a.values[k * plane + i], vb = b.values[zmap[k] * plane + i];
      EXPECT_EQ(std::isnan(va), std::isnan(vb)) << k << " " << i;
      if (std::isnan(vb)) {
        ++missing;
      } else {
        EXPECT_EQ(va, vb) << k << " " << i;
      }
    }
  }
  // Level k (0 = top) has the fill value at 3 + k, and at 7 (NaN in the GRIB input).
  EXPECT_EQ(missing, 4u);
}

TEST(GribSampleTest, IrregularOrTooSmallGridsAreRefused) {
  synthetic::SampleGrid grid({6, 5, 2});
  grid.lon[2] += 1e-6;
  testing::expect_error([&] { synthetic::check_grib_regular_grid(grid); },
                        ErrorCode::kInvalidArgument, {"longitude", "not regular"});
  const synthetic::SampleGrid narrow({1, 5, 2});
  testing::expect_error([&] { synthetic::check_grib_regular_grid(narrow); },
                        ErrorCode::kInvalidArgument, {"longitude", "at least 2"});
  const testing::TempDir dir;
  synthetic::SampleSpec spec;
  spec.dims = {6, 5, 2};
  spec.steps = 1;
  spec.format = synthetic::SampleFormat::kGrib2;
  spec.step_seconds = 90;
  spec.steps = 2;
  testing::expect_error([&] { synthetic::write_sample_dataset(spec, dir / "g"); },
                        ErrorCode::kInvalidArgument, {"minutes"});
  EXPECT_FALSE(std::filesystem::exists(dir / "g" / "sample_t000.grib2"));
  spec.step_seconds = 300;
  spec.grib_bits = 40;
  testing::expect_error([&] { synthetic::validate_sample_spec(spec); },
                        ErrorCode::kInvalidArgument, {"bits"});
}

}  // namespace
}  // namespace strielad
