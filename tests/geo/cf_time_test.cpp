// SPDX-License-Identifier: Apache-2.0
// CF time units as instants (lib/geo/cf_time.h): unit words, reference dates with and
// without time and zone, Julian days against published values, and the units and
// calendars refused with a message naming them.
#include <gtest/gtest.h>

#include "geo/cf_time.h"
#include "support/expect_error.h"

namespace strielad::geo {
namespace {

using strielad::testing::expect_error;

TEST(CfTimeTest, JulianDaysOfKnownDates) {
  EXPECT_DOUBLE_EQ(julian_day(2000, 1, 1, 12 * 3600.0), 2451545.0);  // J2000.0
  EXPECT_DOUBLE_EQ(julian_day(1970, 1, 1, 0), 2440587.5);            // Unix epoch
  EXPECT_DOUBLE_EQ(julian_day(1992, 10, 13, 0), 2448908.5);          // Meeus example 25.a
  EXPECT_DOUBLE_EQ(julian_day(1582, 10, 15, 0), 2299160.5);          // first Gregorian day
}

TEST(CfTimeTest, UnitsWithReferenceDateTimeAndZone) {
  const auto sample = parse_cf_time_units("seconds since 2013-04-26 00:00:00", "proleptic_gregorian");
  EXPECT_DOUBLE_EQ(sample.seconds_per_unit, 1.0);
  EXPECT_DOUBLE_EQ(sample.reference_julian_day, 2456408.5);
  EXPECT_DOUBLE_EQ(sample.julian_day(43200), 2456409.0);

  EXPECT_DOUBLE_EQ(parse_cf_time_units("days since 2000-1-1").reference_julian_day, 2451544.5);
  const auto hours = parse_cf_time_units("hours since 1970-01-01T06:00:00Z", "standard");
  EXPECT_DOUBLE_EQ(hours.seconds_per_unit, 3600.0);
  EXPECT_DOUBLE_EQ(hours.julian_day(6), 2440588.0);
  // 12:00 at +02:00 is 10:00 UTC; -0530 is 5.5 h behind UTC.
  EXPECT_DOUBLE_EQ(parse_cf_time_units("minutes since 2000-01-01 12:00 +02:00").reference_julian_day,
                   2451545.0 - 2.0 / 24);
  EXPECT_DOUBLE_EQ(parse_cf_time_units("s since 2000-01-01 12:00:00 -0530").reference_julian_day,
                   2451545.0 + 5.5 / 24);
  EXPECT_NEAR(parse_cf_time_units("seconds since 2000-01-01 12:00:00.5 UTC").reference_julian_day,
              2451545.0 + 0.5 / 86400, 1e-9);
}

TEST(CfTimeTest, StandardCalendarInstantsBefore1582AreJulianDates) {
  // Julian days from cftime 1.6.2: date2num(date, "days since -4713-01-01 12:00:00").
  EXPECT_DOUBLE_EQ(parse_cf_time_units("days since 1000-01-01", "standard").reference_julian_day,
                   2086307.5);
  EXPECT_DOUBLE_EQ(parse_cf_time_units("days since 1000-01-01").reference_julian_day, 2086307.5);
  EXPECT_DOUBLE_EQ(
      parse_cf_time_units("days since 1000-01-01", "proleptic_gregorian").reference_julian_day,
      2086302.5);
  // The Julian calendar is a real calendar: 2000-01-01 12:00 is 13 days after J2000.0.
  EXPECT_DOUBLE_EQ(
      parse_cf_time_units("hours since 2000-01-01 12:00", "julian").reference_julian_day,
      2451558.0);
}

TEST(CfTimeTest, UnitWords) {
  EXPECT_EQ(cf_unit_seconds("Hours"), 3600.0);
  EXPECT_EQ(cf_unit_seconds("min"), 60.0);
  EXPECT_EQ(cf_unit_seconds("d"), 86400.0);
  EXPECT_FALSE(cf_unit_seconds("fortnights").has_value());
  EXPECT_FALSE(cf_unit_seconds("months").has_value());  // not a fixed length
}

TEST(CfTimeTest, MalformedUnitsAndModelCalendarsAreRefused) {
  for (const char* units : {"seconds", "fortnights since 2000-01-01", "seconds since 2000-13-01",
                            "seconds since 2001-02-29", "seconds since 2000/01/01",
                            "seconds since 2000-01-01 25:00", "seconds since 2000-01-01 12:00 tomorrow",
                            "seconds since 2000-01-01 00:00 +15:00"}) {
    expect_error([&] { parse_cf_time_units(units); }, ErrorCode::kInvalidInput, {units});
  }
  expect_error([&] { parse_cf_time_units("days since 2000-01-01", "360_day"); },
               ErrorCode::kUnsupported, {"360_day"});
  expect_error([&] { parse_cf_time_units("days since 2000-01-01", "noleap"); },
               ErrorCode::kUnsupported, {"noleap"});
}

}  // namespace
}  // namespace strielad::geo
