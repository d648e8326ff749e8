// SPDX-License-Identifier: Apache-2.0
// Attributes that would change every value without a word are refused, naming the file,
// variable and attribute: scale_factor 0 (every value add_offset), an inverted
// valid_range or valid_min above valid_max (every value missing). Such a variable is
// still scanned and listed; only converting it is refused, and it does not stop another
// variable of the same file from being converted.
#include <gtest/gtest.h>

#include <netcdf.h>

#include <cmath>
#include <limits>

#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "support/expect_error.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

std::filesystem::path write(const TempDir& dir, int type, std::vector<NcAttr> attrs) {
  SimpleGrid g;
  const auto path = dir / "bad.nc";
  NetcdfFixture()
      .grid(g)
      .variable("T", type, g.dims(), ramp(g.samples()), std::move(attrs))
      .variable("good", NC_FLOAT, g.dims(), ramp(g.samples()))
      .write(path);
  return path;
}

void read_variable(const std::filesystem::path& path, const std::string& name) {
  ScanOptions options;
  options.variables = {name};
  const InputCatalog c = scan_inputs({path}, options);
  SlabReader reader(c, options);
  std::vector<double> v(c.dims().count());
  reader.read(0, 0, 0, c.dims().z, v);
}

TEST(UnusableValueAttributesTest, ScaleFactorZeroIsRefused) {
  TempDir dir;
  const auto path = write(dir, NC_SHORT,
                          {NcAttr::number("scale_factor", NC_FLOAT, {0}),
                           NcAttr::number("add_offset", NC_FLOAT, {273.5})});
  expect_error([&] { read_variable(path, "T"); }, ErrorCode::kInvalidInput,
               {path.string(), "variable 'T'", "scale_factor is 0", "add_offset (273.5)"});
}

TEST(UnusableValueAttributesTest, NonFiniteScaleFactorOrAddOffsetIsRefused) {
  TempDir dir;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto path = write(dir, NC_SHORT, {NcAttr::number("scale_factor", NC_FLOAT, {nan})});
  expect_error([&] { read_variable(path, "T"); }, ErrorCode::kInvalidInput,
               {path.string(), "variable 'T'", "scale_factor is nan"});
  path = write(dir, NC_SHORT, {NcAttr::number("add_offset", NC_DOUBLE, {-HUGE_VAL})});
  expect_error([&] { read_variable(path, "T"); }, ErrorCode::kInvalidInput,
               {path.string(), "variable 'T'", "add_offset is -inf"});
}

TEST(UnusableValueAttributesTest, InvertedValidRangeIsRefused) {
  TempDir dir;
  const auto path = write(dir, NC_INT, {NcAttr::number("valid_range", NC_INT, {20, 3})});
  expect_error([&] { read_variable(path, "T"); }, ErrorCode::kInvalidInput,
               {path.string(), "variable 'T'", "valid_range [20, 3] is inverted",
                "every value would be missing"});
}

TEST(UnusableValueAttributesTest, ValidMinAboveValidMaxIsRefused) {
  TempDir dir;
  const auto path = write(dir, NC_FLOAT,
                          {NcAttr::number("valid_min", NC_FLOAT, {20}),
                           NcAttr::number("valid_max", NC_FLOAT, {3})});
  expect_error([&] { read_variable(path, "T"); }, ErrorCode::kInvalidInput,
               {path.string(), "variable 'T'", "valid_min 20 is above valid_max 3"});
}

TEST(UnusableValueAttributesTest, InfiniteValidMinIsRefused) {
  TempDir dir;
  const auto path = write(dir, NC_DOUBLE, {NcAttr::number("valid_min", NC_DOUBLE, {HUGE_VAL})});
  expect_error([&] { read_variable(path, "T"); }, ErrorCode::kInvalidInput,
               {path.string(), "variable 'T'", "valid_min is +Inf"});
}

TEST(UnusableValueAttributesTest, ValidMinEqualToValidMaxIsAllowed) {
  TempDir dir;
  const auto path = write(dir, NC_INT,
                          {NcAttr::number("valid_min", NC_INT, {5}),
                           NcAttr::number("valid_max", NC_INT, {5})});
  EXPECT_NO_THROW(read_variable(path, "T"));
}

TEST(UnusableValueAttributesTest, OtherVariablesOfTheFileStillConvert) {
  TempDir dir;
  const auto path = write(dir, NC_SHORT, {NcAttr::number("scale_factor", NC_FLOAT, {0})});
  // Scanning lists it with its attributes...
  const InputCatalog all = scan_inputs({path}, {});
  ASSERT_EQ(all.variables.size(), 2u);
  EXPECT_EQ(all.variables[all.variable_index("T")].scale_factor, 0.0);
  // ...and the other variable reads as usual.
  EXPECT_NO_THROW(read_variable(path, "good"));
}

}  // namespace
}  // namespace strielad::ingest
