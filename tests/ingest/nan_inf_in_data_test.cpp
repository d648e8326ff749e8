// SPDX-License-Identifier: Apache-2.0
// NaN/Inf not declared missing is refused, naming the sample, unless nan_as_fill.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "support/expect_error.h"
#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Grid 4 lon x 3 lat x 3 levels, 2 steps; returns the flat index of (step, lev, lat, lon).
std::size_t at(std::size_t t, std::size_t k, std::size_t j, std::size_t i) {
  return ((t * 3 + k) * 3 + j) * 4 + i;
}

std::filesystem::path write(const TempDir& dir, int type, double bad, std::vector<NcAttr> attrs = {}) {
  SimpleGrid g;
  g.time = {0, 6};
  g.lev = {1000, 850, 700};
  auto data = ramp(g.samples(), 1.0);
  data[at(1, 2, 1, 3)] = bad;  // step 1, level 2, lat 1, lon 3
  const auto path = dir / "clw.nc";
  NetcdfFixture().grid(g).variable("clw", type, g.dims(), data, attrs).write(path);
  return path;
}

TEST(NanInfInDataTest, NaNIsRefusedWithSamplePosition) {
  TempDir dir;
  const auto path = write(dir, NC_FLOAT, kNaN);
  const InputCatalog c = scan_inputs({path}, {});
  SlabReader reader(c, {});
  std::vector<float> out(3 * 3 * 4);
  reader.read(0, 0, 0, 3, out);  // step 0 is clean
  expect_error([&] { reader.read(0, 1, 0, 3, out); }, ErrorCode::kInvalidInput,
               {path.string() + ": variable 'clw' time step 1: sample (lon 3, lat 1, level 2) is "
                                "NaN; pass --nan-as-fill to treat NaN/Inf as missing"});
  // Level numbers are absolute even when the slab starts higher up.
  std::vector<float> top(3 * 4);
  expect_error([&] { reader.read(0, 1, 2, 3, top); }, ErrorCode::kInvalidInput,
               {"(lon 3, lat 1, level 2) is NaN"});
}

TEST(NanInfInDataTest, InfinityInDoubleDataIsRefused) {
  TempDir dir;
  const auto path = write(dir, NC_DOUBLE, -kInf);
  const InputCatalog c = scan_inputs({path}, {});
  SlabReader reader(c, {});
  std::vector<double> out(3 * 3 * 4);
  expect_error([&] { reader.read(0, 1, 0, 3, out); }, ErrorCode::kInvalidInput,
               {"variable 'clw' time step 1: sample (lon 3, lat 1, level 2) is -Inf"});
}

TEST(NanInfInDataTest, NanAsFillTurnsThemIntoMissing) {
  TempDir dir;
  const auto path = write(dir, NC_FLOAT, kInf);
  ScanOptions o;
  o.nan_as_fill = true;
  const InputCatalog c = scan_inputs({path}, o);
  SlabReader reader(c, o);
  std::vector<float> out(3 * 3 * 4);
  reader.read(0, 1, 0, 3, out);
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (i == at(0, 2, 1, 3)) {
      EXPECT_TRUE(std::isnan(out[i]));
    } else {
      EXPECT_EQ(out[i], static_cast<float>(1.0 + static_cast<double>(at(1, 0, 0, 0) + i)));
    }
  }
}

TEST(NanInfInDataTest, NaNDeclaredAsFillValueIsMissingNotAnError) {
  TempDir dir;
  const auto path = write(dir, NC_FLOAT, kNaN, {NcAttr::number("_FillValue", NC_FLOAT, {kNaN})});
  const InputCatalog c = scan_inputs({path}, {});
  SlabReader reader(c, {});
  std::vector<float> out(3 * 3 * 4);
  reader.read(0, 1, 0, 3, out);
  EXPECT_TRUE(std::isnan(out[at(0, 2, 1, 3)]));
  EXPECT_EQ(out[0], static_cast<float>(1.0 + static_cast<double>(at(1, 0, 0, 0))));
}

}  // namespace
}  // namespace strielad::ingest
