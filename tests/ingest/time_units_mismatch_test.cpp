// SPDX-License-Identifier: Apache-2.0
// Time values are only comparable across files in the same units and calendar.
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

TEST(TimeUnitsMismatchTest, DifferentUnitsNameBothFilesAndBothUnits) {
  TempDir dir;
  SimpleGrid a, b;
  a.time = {0};
  a.time_units = "hours since 2000-01-01 00:00:00";
  b.time = {1};
  b.time_units = "days since 2000-01-01 00:00:00";
  write(dir / "hours.nc", a);
  write(dir / "days.nc", b);
  expect_error([&] { scan_inputs({dir / "hours.nc", dir / "days.nc"}, {}); },
               ErrorCode::kInvalidInput,
               {"days.nc", "hours.nc", "'days since 2000-01-01 00:00:00'",
                "'hours since 2000-01-01 00:00:00'"});
}

TEST(TimeUnitsMismatchTest, DifferentCalendar) {
  TempDir dir;
  SimpleGrid a, b;
  b.time = {6};
  b.calendar = "360_day";
  write(dir / "a.nc", a);
  write(dir / "b.nc", b);
  expect_error([&] { scan_inputs({dir / "a.nc", dir / "b.nc"}, {}); }, ErrorCode::kInvalidInput,
               {"b.nc", "calendar '360_day'", "a.nc", "calendar 'standard'"});
}

TEST(TimeUnitsMismatchTest, GregorianAndStandardAreTheSameCalendar) {
  TempDir dir;
  SimpleGrid a, b;
  b.time = {6};
  b.calendar = "gregorian";
  write(dir / "a.nc", a);
  write(dir / "b.nc", b);
  const InputCatalog c = scan_inputs({dir / "a.nc", dir / "b.nc"}, {});
  EXPECT_EQ(c.time.values, (std::vector<double>{0, 6}));
  EXPECT_EQ(c.time.calendar, "standard");
}

TEST(TimeUnitsMismatchTest, FileWithoutTimeMixedWithTimeSeries) {
  TempDir dir;
  SimpleGrid a, b;
  b.with_time = false;
  write(dir / "a.nc", a);
  write(dir / "static.nc", b);
  expect_error([&] { scan_inputs({dir / "a.nc", dir / "static.nc"}, {}); },
               ErrorCode::kInvalidInput, {"static.nc", "no time dimension", "a.nc", "hours since"});
}

}  // namespace
}  // namespace strielad::ingest
