// SPDX-License-Identifier: Apache-2.0
// A NaN _FillValue (xarray's default), a NaN or infinite missing_value and a NaN
// valid_min convert into a store that opens: the manifest leaves the non-finite value out
// (JSON has none; it wrote null before and the converter rejected its own store, "key
// 'fill_value' has the wrong type"), and the samples are missing exactly where the
// attribute says so, like with any fill.
#include <gtest/gtest.h>

#include <netcdf.h>

#include <cmath>
#include <limits>

#include "convert/converter.h"
#include "store/store.h"
#include "support/netcdf_fixture.h"
#include "support/store_level0.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using namespace strielad::testing;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

build::ConvertOptions options_for(std::vector<std::filesystem::path> inputs,
                                  const std::filesystem::path& store) {
  build::ConvertOptions o;
  o.inputs = std::move(inputs);
  o.store = store;
  o.brick = 2;
  o.threads = 2;
  return o;
}

std::uint64_t valid_count(const Store& store, std::uint32_t step, std::uint32_t var) {
  return store.index(step, var).back().valid_count;  // the root's count is the step's
}

TEST(NanCfAttributesRoundTripTest, NanFillValueAndInfiniteMissingValueMakeSamplesMissing) {
  TempDir dir;
  SimpleGrid g;
  auto t = ramp(g.samples(), 1.0);
  t[3] = kNaN;
  t[17] = kNaN;
  auto q = ramp(g.samples(), 0.5);
  q[5] = -kInf;
  NetcdfFixture()
      .grid(g)
      .variable("T", NC_FLOAT, g.dims(), t, {NcAttr::number("_FillValue", NC_FLOAT, {kNaN})})
      .variable("Q", NC_DOUBLE, g.dims(), q,
                {NcAttr::number("_FillValue", NC_DOUBLE, {kNaN}),
                 NcAttr::number("missing_value", NC_DOUBLE, {-kInf})})
      .write(dir / "xarray.nc");

  // Without --nan-as-fill: NaN is declared missing, so it is no error.
  build::convert(options_for({dir / "xarray.nc"}, dir / "store"));
  const auto store = Store::open(dir / "store");
  const format::Manifest& m = store->manifest();
  const std::size_t vt = m.variable_index("T"), vq = m.variable_index("Q");
  EXPECT_FALSE(m.variables[vt].fill_value.has_value());
  EXPECT_FALSE(m.variables[vq].fill_value.has_value());
  EXPECT_FALSE(m.variables[vq].missing_value.has_value());
  EXPECT_FALSE(m.nan_as_fill);

  const auto got_t = assemble_level0(*store, 0, static_cast<std::uint32_t>(vt));
  const auto got_q = assemble_level0(*store, 0, static_cast<std::uint32_t>(vq));
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (std::isnan(t[i])) {
      EXPECT_TRUE(std::isnan(got_t[i])) << i;
    } else {
      EXPECT_EQ(got_t[i], static_cast<double>(static_cast<float>(t[i]))) << i;
    }
    if (std::isinf(q[i])) {
      EXPECT_TRUE(std::isnan(got_q[i])) << i;
    } else {
      EXPECT_EQ(got_q[i], q[i]) << i;
    }
  }
  EXPECT_EQ(valid_count(*store, 0, static_cast<std::uint32_t>(vt)), t.size() - 2);
  EXPECT_EQ(valid_count(*store, 0, static_cast<std::uint32_t>(vq)), q.size() - 1);
}

TEST(NanCfAttributesRoundTripTest, NanValidMinBoundsNothingAcrossFiles) {
  TempDir dir;
  std::vector<std::filesystem::path> files;
  for (int step = 0; step < 2; ++step) {
    SimpleGrid g;
    g.time = {static_cast<double>(step)};
    auto data = ramp(g.samples(), -5.0);
    data[7] = kNaN;
    const auto path = dir / ("step" + std::to_string(step) + ".nc");
    NetcdfFixture()
        .grid(g)
        .variable("T", NC_FLOAT, g.dims(), data,
                  {NcAttr::number("_FillValue", NC_FLOAT, {kNaN}),
                   NcAttr::number("valid_min", NC_FLOAT, {kNaN}),
                   NcAttr::number("valid_max", NC_FLOAT, {10})})
        .write(path);
    files.push_back(path);
  }
  // Two files: their NaN bounds must compare equal (they are no bounds at all).
  build::convert(options_for(files, dir / "store"));
  const auto store = Store::open(dir / "store");
  const format::StoreVariable& v = store->manifest().variables.at(0);
  EXPECT_FALSE(v.valid_min.has_value());
  EXPECT_EQ(v.valid_max, 10.0);
  EXPECT_FALSE(v.fill_value.has_value());

  const SimpleGrid g;
  const auto data = ramp(g.samples(), -5.0);
  for (std::uint32_t step = 0; step < 2; ++step) {
    const auto got = assemble_level0(*store, step, 0);
    std::size_t valid = 0;
    for (std::size_t i = 0; i < data.size(); ++i) {
      if (i == 7 || data[i] > 10) {  // the NaN fill, and above valid_max
        EXPECT_TRUE(std::isnan(got[i])) << i;
      } else {
        EXPECT_EQ(got[i], data[i]) << i;  // every value below 0 kept: no lower bound
        ++valid;
      }
    }
    EXPECT_EQ(valid_count(*store, step, 0), valid);
  }
}

TEST(NanCfAttributesRoundTripTest, UndeclaredInfinityIsStillRefusedNextToANanFill) {
  TempDir dir;
  SimpleGrid g;
  auto t = ramp(g.samples());
  t[2] = kNaN;
  t[4] = kInf;
  NetcdfFixture()
      .grid(g)
      .variable("T", NC_FLOAT, g.dims(), t, {NcAttr::number("_FillValue", NC_FLOAT, {kNaN})})
      .write(dir / "inf.nc");
  try {
    build::convert(options_for({dir / "inf.nc"}, dir / "store"));
    ADD_FAILURE() << "converted +Inf that no attribute declares missing";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kInvalidInput) << e.what();
    EXPECT_NE(std::string(e.what()).find("+Inf"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace strielad
