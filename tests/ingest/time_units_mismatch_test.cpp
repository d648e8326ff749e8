// SPDX-License-Identifier: Apache-2.0
// Time values of files in other units are reconciled into the first file's units (the
// same instant, to the millisecond; ICON's absolute days into Unix seconds); calendars
// must agree.
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

TEST(TimeUnitsMismatchTest, OtherUnitsAreReconciledIntoTheFirstFilesUnits) {
  TempDir dir;
  SimpleGrid a, b, c;
  a.time = {0, 6};
  a.time_units = "hours since 2000-01-01 00:00:00";
  b.time = {0.5, 1};  // 12:00 and 24:00 on the 1st
  b.time_units = "days since 2000-01-01 00:00:00";
  c.time = {-1800};  // 2000-01-02 06:30 UTC, in minutes since another date and zone
  c.time_units = "minutes since 2000-01-03 13:30:00 +01:00";
  write(dir / "hours.nc", a);
  write(dir / "days.nc", b);
  write(dir / "minutes.nc", c);
  const InputCatalog cat =
      scan_inputs({dir / "hours.nc", dir / "days.nc", dir / "minutes.nc"}, {});
  EXPECT_EQ(cat.time.units, "hours since 2000-01-01 00:00:00");
  EXPECT_EQ(cat.time.values, (std::vector<double>{0, 6, 12, 24, 30.5}));
  EXPECT_EQ(cat.locations[0][2].file, 1u);  // 12 h is the days file's first step
  EXPECT_EQ(cat.locations[0][4].file, 2u);
  EXPECT_EQ(cat.locations[0][4].time_in_file, 0u);
}

TEST(TimeUnitsMismatchTest, OneInstantInTwoUnitsIsADuplicate) {
  TempDir dir;
  SimpleGrid a, b;
  a.time = {24};
  a.time_units = "hours since 2000-01-01 00:00:00";
  b.time = {1};
  b.time_units = "days since 2000-01-01 00:00:00";
  write(dir / "hours.nc", a);
  write(dir / "days.nc", b);
  expect_error([&] { scan_inputs({dir / "hours.nc", dir / "days.nc"}, {}); },
               ErrorCode::kInvalidInput, {"duplicate time step", "hours.nc", "days.nc", "24"});
}

TEST(TimeUnitsMismatchTest, IconAbsoluteDaysBecomeUnixSeconds) {
  TempDir dir;
  SimpleGrid a, b;
  a.time = {20130426.5, 20130426.75};
  a.time_units = "day as %Y%m%d.%f";
  a.calendar = "proleptic_gregorian";
  b.time = {1367000000};  // 2013-04-26 18:13:20 UTC
  b.time_units = "seconds since 1970-01-01";
  b.calendar = "proleptic_gregorian";
  write(dir / "icon.nc", a);
  write(dir / "unix.nc", b);
  const InputCatalog cat = scan_inputs({dir / "icon.nc", dir / "unix.nc"}, {});
  EXPECT_EQ(cat.time.units, "seconds since 1970-01-01 00:00:00");
  EXPECT_EQ(cat.time.calendar, "proleptic_gregorian");
  // 2013-04-26 is day 15821 of the Unix epoch.
  EXPECT_EQ(cat.time.values, (std::vector<double>{15821 * 86400.0 + 43200,
                                                  15821 * 86400.0 + 64800, 1367000000}));
  SimpleGrid bad = a;
  bad.time = {20130230.5};
  write(dir / "bad.nc", bad);
  expect_error([&] { scan_inputs({dir / "bad.nc"}, {}); }, ErrorCode::kInvalidInput,
               {"bad.nc", "20130230.5", "not a date"});
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
