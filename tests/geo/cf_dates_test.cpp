// SPDX-License-Identifier: Apache-2.0
// Dates of CF time values (lib/geo/cf_time.h: parse_cf_time_reference, cf_date_text) in
// every CF calendar. The expected strings come from independent references, not from
// this code: Python's datetime (datetime(1949, 12, 1) + timedelta(days=20500.5)) for the
// Gregorian calendars after 1582, cftime 1.6.2 (the netCDF4-python time library,
// num2date(value, units, calendar).isoformat()) for every calendar, and hand counts
// for 360_day and noleap (written out beside them).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "geo/cf_time.h"
#include "support/expect_error.h"

namespace strielad::geo {
namespace {

using strielad::testing::expect_error;

std::string date(const std::string& units, const std::string& calendar, double value) {
  return cf_date_text(parse_cf_time_reference(units, calendar), value);
}

TEST(CfDatesTest, ProlepticGregorianAndStandardMatchPythonDatetime) {
  // nug/tas_rotated_grid_EUR11.nc of libncarg-data: time = 20500.5.
  EXPECT_EQ(date("days since 1949-12-01 00:00:00", "proleptic_gregorian", 20500.5),
            "2006-01-16T12:00:00Z");
  // nug/rectilinear_grid_3D.nc: time = 0.
  EXPECT_EQ(date("hours since 2001-01-01 00:00:00", "standard", 0), "2001-01-01T00:00:00Z");
  EXPECT_EQ(date("hours since 1900-01-01", "standard", 973356), "2011-01-15T12:00:00Z");
  EXPECT_EQ(date("hours since 1900-01-01", "proleptic_gregorian", 973356),
            "2011-01-15T12:00:00Z");
  EXPECT_EQ(date("hours since 1900-01-01", "", 973356), "2011-01-15T12:00:00Z");  // standard
  EXPECT_EQ(date("days since 1-1-1", "proleptic_gregorian", 730119), "2000-01-01T00:00:00Z");
}

TEST(CfDatesTest, StandardCalendarIsJulianBefore1582) {
  // cftime: the mixed calendar skips 1582-10-05 .. 1582-10-14.
  EXPECT_EQ(date("days since 1582-10-04", "standard", 1), "1582-10-15T00:00:00Z");
  EXPECT_EQ(date("days since 1582-10-15", "gregorian", -1), "1582-10-04T00:00:00Z");
  // From 1-1-1 the standard calendar is two days behind the proleptic Gregorian by 2000.
  EXPECT_EQ(date("days since 1-1-1", "standard", 0), "0001-01-01T00:00:00Z");
  EXPECT_EQ(date("days since 1-1-1", "standard", 730119), "1999-12-30T00:00:00Z");
  // cdf/vinth2p.nc of libncarg-data: "days since 0049-09-01 00:00:00", no calendar.
  EXPECT_EQ(date("days since 0049-09-01 00:00:00", "", 107), "0049-12-17T00:00:00Z");
  EXPECT_EQ(date("days since 0049-09-01 00:00:00", "", 108), "0049-12-18T00:00:00Z");
  EXPECT_EQ(date("days since 1000-02-29", "standard", -36500), "0900-03-25T00:00:00Z");
  EXPECT_EQ(date("days since 1900-02-28", "standard", 1), "1900-03-01T00:00:00Z");
}

TEST(CfDatesTest, JulianCalendar) {
  // cftime.
  EXPECT_EQ(date("hours since 1900-01-01", "julian", 973356), "2011-01-14T12:00:00Z");
  EXPECT_EQ(date("days since 1-1-1", "julian", 730119), "1999-12-17T00:00:00Z");
  EXPECT_EQ(date("days since 1900-02-28", "julian", 1), "1900-02-29T00:00:00Z");
  EXPECT_EQ(date("days since 1000-02-29", "julian", 366), "1001-03-01T00:00:00Z");
}

TEST(CfDatesTest, ModelCalendars) {
  // 973356 h = 40556.5 days. 360_day: 40556 = 112 * 360 + 236, day 236 of a year is
  // month 236 / 30 + 1 = 8, day 236 - 210 + 1 = 27: 2012-08-27 12:00 (cftime agrees).
  EXPECT_EQ(date("hours since 1900-01-01", "360_day", 973356), "2012-08-27T12:00:00Z");
  // noleap: 40556 = 111 * 365 + 41, day 41 of a year is February 11: 2011-02-11 12:00.
  EXPECT_EQ(date("hours since 1900-01-01", "noleap", 973356), "2011-02-11T12:00:00Z");
  EXPECT_EQ(date("hours since 1900-01-01", "365_day", 973356), "2011-02-11T12:00:00Z");
  // all_leap: 40556 = 110 * 366 + 296, day 296 (0-based) of a 366-day year is
  // October 23 (October starts on day 274): 2010-10-23 12:00 (cftime agrees).
  EXPECT_EQ(date("hours since 1900-01-01", "all_leap", 973356), "2010-10-23T12:00:00Z");
  EXPECT_EQ(date("hours since 1900-01-01", "366_day", 973356), "2010-10-23T12:00:00Z");
  // 59 days after January 1st in 360_day: two 30-day months less a day: February 30.
  EXPECT_EQ(date("days since 2000-01-01", "360_day", 59), "2000-02-30T00:00:00Z");
  EXPECT_EQ(date("days since 2000-01-01", "360_day", -1), "1999-12-30T00:00:00Z");
  // 10817.25 days = 30 years of 360 days + 17.25 days (cftime agrees).
  EXPECT_EQ(date("days since 2000-01-01", "360_day", 10817.25), "2030-01-18T06:00:00Z");
  EXPECT_EQ(date("days since 2001-02-28", "all_leap", 1), "2001-02-29T00:00:00Z");
  EXPECT_EQ(date("days since 2000-02-28", "noleap", 1), "2000-03-01T00:00:00Z");
  EXPECT_EQ(date("days since 2000-02-28", "noleap", -365), "1999-02-28T00:00:00Z");
  // A reference date of the 360-day calendar that no real calendar has.
  EXPECT_EQ(date("days since 2000-02-30", "360_day", 1), "2000-03-01T00:00:00Z");
}

TEST(CfDatesTest, UnitWordsFractionalAndNegativeValues) {
  EXPECT_EQ(date("hours since 1970-01-01", "standard", -1), "1969-12-31T23:00:00Z");
  EXPECT_EQ(date("hour since 1970-01-01", "standard", 25), "1970-01-02T01:00:00Z");
  EXPECT_EQ(date("hrs since 1970-01-01", "standard", 1.5), "1970-01-01T01:30:00Z");
  EXPECT_EQ(date("d since 1970-1-1", "standard", 1.5), "1970-01-02T12:00:00Z");
  EXPECT_EQ(date("s since 1970-01-01", "standard", 86399), "1970-01-01T23:59:59Z");
  EXPECT_EQ(date("sec since 1970-01-01", "standard", -0.5), "1969-12-31T23:59:59.500Z");
  EXPECT_EQ(date("seconds since 2000-01-01", "standard", 0.25), "2000-01-01T00:00:00.250Z");
  EXPECT_EQ(date("minutes since 2013-04-26T12:00:00Z", "standard", 90), "2013-04-26T13:30:00Z");
  EXPECT_EQ(date("Days since 2000-01-01 06:00", "standard", -0.25), "2000-01-01T00:00:00Z");
  EXPECT_EQ(date("milliseconds since 2000-01-01", "standard", 1500), "2000-01-01T00:00:01.500Z");
  EXPECT_EQ(date("weeks since 2000-01-01", "standard", 2), "2000-01-15T00:00:00Z");
  // A tenth of an hour, which a double cannot hold exactly, is still 6 minutes.
  EXPECT_EQ(date("hours since 2000-01-01", "standard", 0.1), "2000-01-01T00:06:00Z");
}

TEST(CfDatesTest, ReferenceZoneOffsetIsAppliedAndDatesAreUtc) {
  // 00:00 at UTC+1 is 23:00 UTC the day before (cftime, with "+01:00"; udunits reads
  // "+1:00" as the same offset).
  EXPECT_EQ(date("hours since 1970-01-01 00:00:00 +1:00", "standard", 0), "1969-12-31T23:00:00Z");
  EXPECT_EQ(date("hours since 1970-01-01 00:00:00 +01:00", "standard", 0), "1969-12-31T23:00:00Z");
  EXPECT_EQ(date("hours since 1970-01-01 00:00:00 -06:00", "standard", 0), "1970-01-01T06:00:00Z");
  EXPECT_EQ(date("hours since 1970-01-01 00:00:00+0100", "noleap", 0), "1969-12-31T23:00:00Z");
  EXPECT_EQ(date("seconds since 2000-01-01 12:00:00.5 UTC", "", 0), "2000-01-01T12:00:00.500Z");
}

TEST(CfDatesTest, YearsBeforeOneAndFarFuture) {
  // The standard and julian calendars have no year 0: the day before 0001-01-01 is
  // 1 BC (cftime writes -0001-12-31), which ISO 8601 numbers 0000.
  EXPECT_EQ(date("days since 0001-01-01", "standard", -1), "0000-12-31T00:00:00Z");
  EXPECT_EQ(date("days since -1-12-31", "julian", 1), "0001-01-01T00:00:00Z");
  expect_error([] { parse_cf_time_reference("days since 0000-01-01", "standard"); },
               ErrorCode::kInvalidInput, {"year 0", "standard"});
  // The other calendars count years as ISO 8601 does (cftime: -0031-12-31 in noleap).
  EXPECT_EQ(date("days since 1970-01-01", "noleap", -365 * 2000 - 1), "-0031-12-31T00:00:00Z");
  EXPECT_EQ(date("days since 0000-01-01", "proleptic_gregorian", 0), "0000-01-01T00:00:00Z");
  EXPECT_EQ(date("days since 9999-12-31", "proleptic_gregorian", 1), "+10000-01-01T00:00:00Z");
}

TEST(CfDatesTest, ValuesWithoutADateSayWhy) {
  const auto r = parse_cf_time_reference("days since 2000-01-01", "standard");
  expect_error([&] { cf_date_text(r, std::numeric_limits<double>::quiet_NaN()); },
               ErrorCode::kInvalidArgument, {"not finite"});
  expect_error([&] { cf_date_text(r, 1e300); }, ErrorCode::kInvalidArgument,
               {"1e+300", "too far"});
}

TEST(CfDatesTest, UnitsThatGiveNoDatesSayWhy) {
  // cdf/contour.cdf: "hours"; cdf/nc4uvt.nc: "Month" (no reference date).
  expect_error([] { parse_cf_time_reference("hours", ""); }, ErrorCode::kInvalidInput,
               {"'hours'", "no reference date"});
  expect_error([] { parse_cf_time_reference("Month", ""); }, ErrorCode::kInvalidInput,
               {"'Month'", "no reference date"});
  expect_error([] { parse_cf_time_reference("months since 2000-01-01", "standard"); },
               ErrorCode::kUnsupported, {"months since 2000-01-01", "not a fixed length"});
  expect_error([] { parse_cf_time_reference("years since 0001-01-01", "noleap"); },
               ErrorCode::kUnsupported, {"not a fixed length"});
  expect_error([] { parse_cf_time_reference("fortnights since 2000-01-01", ""); },
               ErrorCode::kInvalidInput, {"unknown unit 'fortnights'"});
  expect_error([] { parse_cf_time_reference("", ""); }, ErrorCode::kInvalidInput, {"no units"});
  expect_error([] { parse_cf_time_reference("days since 2000-01-01", "none"); },
               ErrorCode::kUnsupported, {"'none'", "no calendar"});
  expect_error([] { parse_cf_time_reference("days since 2000-01-01", "lunar"); },
               ErrorCode::kUnsupported, {"'lunar'"});
  // Reference dates that are not days of the calendar.
  expect_error([] { parse_cf_time_reference("days since 2001-02-29", "noleap"); },
               ErrorCode::kInvalidInput, {"2001-02-29", "noleap"});
  expect_error([] { parse_cf_time_reference("days since 2000-02-29", "noleap"); },
               ErrorCode::kInvalidInput, {"noleap"});
  expect_error([] { parse_cf_time_reference("days since 2000-02-30", "standard"); },
               ErrorCode::kInvalidInput, {"standard"});
  expect_error([] { parse_cf_time_reference("days since 1582-10-10", "standard"); },
               ErrorCode::kInvalidInput, {"1582-10-10", "standard"});
}

}  // namespace
}  // namespace strielad::geo
