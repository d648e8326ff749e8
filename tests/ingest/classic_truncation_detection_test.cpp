// SPDX-License-Identifier: Apache-2.0
// netCDF-C reads past the end of a truncated classic file as zeros, so the size a classic
// header implies is checked: exact for intact files of every classic flavour, and one
// byte less is caught.
#include <gtest/gtest.h>

#include <netcdf.h>

#include "core/file_io.h"
#include "ingest/classic_layout.h"
#include "support/expect_error.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

void write(const std::filesystem::path& path, int cmode, bool two_record_vars) {
  SimpleGrid g;
  g.time = {0, 6, 12};
  NetcdfFixture f(cmode);
  f.grid(g).variable("T", NC_FLOAT, g.dims(), ramp(g.samples()));
  if (two_record_vars) f.variable("U", NC_DOUBLE, g.dims(), ramp(g.samples()));
  f.write(path);
}

class ClassicTruncationDetectionTest : public ::testing::TestWithParam<std::pair<int, bool>> {};

TEST_P(ClassicTruncationDetectionTest, IntactFileHasExactlyTheRequiredSize) {
  TempDir dir;
  const auto path = dir / "c.nc";
  write(path, GetParam().first, GetParam().second);
  const auto bytes = read_file_bytes(path);
  const auto required = classic_required_size(bytes);
  ASSERT_TRUE(required.has_value());
  EXPECT_EQ(*required, bytes.size());
  check_classic_header(path);  // no throw

  copy_truncated(path, dir / "short.nc", bytes.size() - 1);
  expect_error([&] { check_classic_header(dir / "short.nc"); }, ErrorCode::kInvalidInput,
               {"short.nc: file is truncated"});
}

INSTANTIATE_TEST_SUITE_P(Formats, ClassicTruncationDetectionTest,
                         ::testing::Values(std::pair{NC_CLOBBER, false},
                                           std::pair{NC_CLOBBER, true},
                                           std::pair{NC_64BIT_OFFSET, true},
                                           std::pair{NC_64BIT_DATA, false},
                                           std::pair{NC_64BIT_DATA, true}));

// Odd-sized records: a lone record variable is not padded, several are padded to 4 bytes.
// netCDF-C also writes the padding after the last record; only data bytes are required.
TEST(ClassicTruncationDetectionStandaloneTest, OddSizedRecordVariables) {
  for (int cmode : {NC_CLOBBER, NC_64BIT_OFFSET, NC_64BIT_DATA}) {
    for (bool second : {false, true}) {
      TempDir dir;
      const auto path = dir / "odd.nc";
      NetcdfFixture f(cmode);
      f.dimension("rec", 3, true).dimension("x", 5).variable("b", NC_BYTE, {"rec", "x"}, ramp(15));
      if (second) f.variable("s", NC_SHORT, {"rec", "x"}, ramp(15));
      f.variable("fixed", NC_BYTE, {"x"}, ramp(5));
      f.write(path);
      const auto bytes = read_file_bytes(path);
      const auto required = classic_required_size(bytes);
      ASSERT_TRUE(required.has_value());
      EXPECT_LE(*required, bytes.size()) << "cmode " << cmode << " second " << second;
      EXPECT_EQ(*required, second ? bytes.size() - 2 : bytes.size()) << "cmode " << cmode;
      copy_truncated(path, dir / "short.nc", *required - 1);
      expect_error([&] { check_classic_header(dir / "short.nc"); },
                   ErrorCode::kInvalidInput, {"file is truncated"});
    }
  }
}

TEST(ClassicTruncationDetectionStandaloneTest, RealFileAndNonClassicInputs) {
  const auto bytes = read_file_bytes(ncarg_file("cdf/contour.cdf"));
  const auto required = classic_required_size(bytes);
  ASSERT_TRUE(required.has_value());
  EXPECT_LE(*required, bytes.size());
  EXPECT_GT(*required, bytes.size() - 4);
  // HDF5-based files and garbage are not classic: nothing to say.
  EXPECT_FALSE(classic_required_size(read_file_bytes(ncarg_file("cdf/nc4uvt.nc"))).has_value());
  const std::vector<std::byte> junk(100, std::byte{0x43});
  EXPECT_FALSE(classic_required_size(junk).has_value());
  // A header cut short is "need more", not a size.
  EXPECT_FALSE(classic_required_size(std::span(bytes).first(40)).has_value());
}

}  // namespace
}  // namespace strielad::ingest
