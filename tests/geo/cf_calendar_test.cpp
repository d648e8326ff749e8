// SPDX-License-Identifier: Apache-2.0
// CF calendars as day arithmetic (lib/geo/cf_calendar.h): calendar names, which dates
// exist, day numbers of published dates, and day numbers and dates as inverses of each
// other over long spans in every calendar.
#include <gtest/gtest.h>

#include "geo/cf_calendar.h"
#include "support/expect_error.h"

namespace strielad::geo {
namespace {

using strielad::testing::expect_error;

TEST(CfCalendarTest, NamesAndTheirAliases) {
  EXPECT_EQ(parse_cf_calendar(""), CfCalendar::kStandard);  // CF: no attribute is standard
  EXPECT_EQ(parse_cf_calendar("Gregorian"), CfCalendar::kStandard);
  EXPECT_EQ(parse_cf_calendar("proleptic_gregorian"), CfCalendar::kProlepticGregorian);
  EXPECT_EQ(parse_cf_calendar("julian"), CfCalendar::kJulian);
  EXPECT_EQ(parse_cf_calendar("365_day"), CfCalendar::kNoLeap);
  EXPECT_EQ(parse_cf_calendar("NOLEAP"), CfCalendar::kNoLeap);
  EXPECT_EQ(parse_cf_calendar("366_day"), CfCalendar::kAllLeap);
  EXPECT_EQ(parse_cf_calendar("all_leap"), CfCalendar::kAllLeap);
  EXPECT_EQ(parse_cf_calendar("360_day"), CfCalendar::k360Day);
  EXPECT_EQ(parse_cf_calendar("none"), CfCalendar::kNone);
  EXPECT_EQ(cf_calendar_name(CfCalendar::kAllLeap), "all_leap");
  expect_error([] { parse_cf_calendar("lunar"); }, ErrorCode::kUnsupported, {"'lunar'"});
}

TEST(CfCalendarTest, WhichDatesExist) {
  EXPECT_TRUE(cf_date_exists(CfCalendar::kStandard, {2000, 2, 29}));
  EXPECT_FALSE(cf_date_exists(CfCalendar::kStandard, {1900, 2, 29}));
  EXPECT_TRUE(cf_date_exists(CfCalendar::kStandard, {1500, 2, 29}));  // Julian leap year
  EXPECT_FALSE(cf_date_exists(CfCalendar::kProlepticGregorian, {1500, 2, 29}));
  EXPECT_TRUE(cf_date_exists(CfCalendar::kJulian, {1900, 2, 29}));
  EXPECT_TRUE(cf_date_exists(CfCalendar::kStandard, {1582, 10, 4}));
  EXPECT_FALSE(cf_date_exists(CfCalendar::kStandard, {1582, 10, 5}));   // the ten days
  EXPECT_FALSE(cf_date_exists(CfCalendar::kStandard, {1582, 10, 14}));  // that never were
  EXPECT_TRUE(cf_date_exists(CfCalendar::kStandard, {1582, 10, 15}));
  EXPECT_TRUE(cf_date_exists(CfCalendar::kProlepticGregorian, {1582, 10, 10}));
  EXPECT_FALSE(cf_date_exists(CfCalendar::kNoLeap, {2000, 2, 29}));
  EXPECT_TRUE(cf_date_exists(CfCalendar::kAllLeap, {2001, 2, 29}));
  EXPECT_TRUE(cf_date_exists(CfCalendar::k360Day, {2001, 2, 30}));
  EXPECT_FALSE(cf_date_exists(CfCalendar::k360Day, {2001, 1, 31}));
  EXPECT_FALSE(cf_date_exists(CfCalendar::kNone, {2001, 1, 1}));
  EXPECT_FALSE(cf_date_exists(CfCalendar::kStandard, {2001, 13, 1}));
}

TEST(CfCalendarTest, DayNumbersOfPublishedDates) {
  // Real calendars share the Unix epoch: Julian day of 00:00 = 2440587.5 + day number.
  EXPECT_EQ(cf_day_number(CfCalendar::kStandard, {1970, 1, 1}), 0);
  EXPECT_EQ(cf_day_number(CfCalendar::kStandard, {2000, 1, 1}), 10957);  // JD 2451544.5
  EXPECT_EQ(cf_day_number(CfCalendar::kStandard, {1582, 10, 15}), 2299160 - 2440587);
  EXPECT_EQ(cf_day_number(CfCalendar::kStandard, {1582, 10, 4}), 2299159 - 2440587);
  EXPECT_EQ(cf_day_number(CfCalendar::kJulian, {1582, 10, 4}), 2299159 - 2440587);
  EXPECT_EQ(cf_day_number(CfCalendar::kJulian, {1970, 1, 1}), 13);  // Gregorian 1970-01-14
  // JD 0 is noon of the Julian -4712-01-01 (4713 BC); Meeus, Astronomical Algorithms.
  EXPECT_EQ(cf_day_number(CfCalendar::kJulian, {-4712, 1, 1}), -2440588);
  EXPECT_EQ(cf_day_number(CfCalendar::kStandard, {-4712, 1, 1}), -2440588);
  EXPECT_EQ(cf_day_number(CfCalendar::kNoLeap, {1971, 3, 1}), 365 + 59);
  EXPECT_EQ(cf_day_number(CfCalendar::kAllLeap, {1971, 3, 1}), 366 + 60);
  EXPECT_EQ(cf_day_number(CfCalendar::k360Day, {1969, 12, 30}), -1);
  expect_error([] { cf_day_number(CfCalendar::kStandard, {1582, 10, 10}); },
               ErrorCode::kInvalidArgument, {"1582-10-10", "standard"});
  expect_error([] { cf_day_number(CfCalendar::kNone, {2000, 1, 1}); },
               ErrorCode::kInvalidArgument, {"none"});
}

TEST(CfCalendarTest, DayNumbersAndDatesAreInversesInEveryCalendar) {
  for (const CfCalendar c : {CfCalendar::kStandard, CfCalendar::kProlepticGregorian,
                             CfCalendar::kJulian, CfCalendar::kNoLeap, CfCalendar::kAllLeap,
                             CfCalendar::k360Day}) {
    // 1,600,000 days from about 2400 BC to 2400 AD, past the 1582 switch: each day's
    // date exists, gives the day back, and is the day after the previous day's date.
    CfDate previous = cf_date_of_day(c, -800001);
    for (std::int64_t day = -800000; day <= 800000; ++day) {
      const CfDate d = cf_date_of_day(c, day);
      ASSERT_TRUE(cf_date_exists(c, d)) << cf_calendar_name(c) << " day " << day;
      ASSERT_EQ(cf_day_number(c, d), day) << cf_calendar_name(c);
      const bool last_of_month =
          !cf_date_exists(c, {previous.year, previous.month, previous.day + 1});
      const bool next_day = d.year == previous.year && d.month == previous.month &&
                            d.day == previous.day + 1;
      const bool next_month = last_of_month && d.year == previous.year &&
                              d.month == previous.month + 1 && d.day == 1;
      const bool next_year = last_of_month && previous.month == 12 &&
                             d.year == previous.year + 1 && d.month == 1 && d.day == 1;
      const bool gregorian_switch = c == CfCalendar::kStandard && previous == CfDate{1582, 10, 4} &&
                                    d == CfDate{1582, 10, 15};
      ASSERT_TRUE(next_day || next_month || next_year || gregorian_switch)
          << cf_calendar_name(c) << " day " << day << ": " << d.year << "-" << d.month << "-"
          << d.day;
      previous = d;
    }
  }
}

}  // namespace
}  // namespace strielad::geo
