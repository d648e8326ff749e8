// SPDX-License-Identifier: Apache-2.0
// Each (variable, time) must come from exactly one file.
#include <gtest/gtest.h>

#include "support/expect_error.h"
#include "ingest/input_catalog.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad::ingest {
namespace {

using namespace strielad::testing;

void write(const std::filesystem::path& path, SimpleGrid g) {
  NetcdfFixture().grid(g).variable("T", NC_FLOAT, g.dims(), ramp(g.samples())).write(path);
}

TEST(DuplicateTimeTest, OverlappingFilesNameTimeAndBothFiles) {
  TempDir dir;
  SimpleGrid a, b;
  a.time = {0, 6};
  b.time = {6, 12};
  write(dir / "a.nc", a);
  write(dir / "b.nc", b);
  expect_error([&] { scan_inputs({dir / "a.nc", dir / "b.nc"}, {}); }, ErrorCode::kInvalidInput,
               {"variable 'T' time 6 (hours since 2000-01-01 00:00:00)", "a.nc", "b.nc",
                "duplicate"});
}

TEST(DuplicateTimeTest, SameFileTwiceIsAnInvalidArgument) {
  TempDir dir;
  write(dir / "a.nc", SimpleGrid{});
  expect_error([&] { scan_inputs({dir / "a.nc", dir / "." / "a.nc"}, {}); },
               ErrorCode::kInvalidArgument, {"a.nc", "given twice"});
}

TEST(DuplicateTimeTest, TwoFilesWithoutTimeHoldingTheSameVariable) {
  TempDir dir;
  SimpleGrid g;
  g.with_time = false;
  write(dir / "a.nc", g);
  write(dir / "b.nc", g);
  expect_error([&] { scan_inputs({dir / "a.nc", dir / "b.nc"}, {}); }, ErrorCode::kInvalidInput,
               {"variable 'T' has no time dimension in both", "a.nc", "b.nc"});
}

}  // namespace
}  // namespace strielad::ingest
