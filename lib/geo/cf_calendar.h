// SPDX-License-Identifier: Apache-2.0
// The calendars of CF time coordinates (CF conventions 1.11, section 4.4.3 "Calendar")
// as day arithmetic: a date of a calendar <-> a count of days in that calendar.
//   standard (gregorian): the Julian calendar up to 1582-10-04, the Gregorian from
//     1582-10-15 on (the ten days between do not exist);
//   proleptic_gregorian: the Gregorian calendar for every date;
//   julian: the Julian calendar (a leap year every 4 years);
//   noleap (365_day), all_leap (366_day), 360_day (twelve 30-day months): model years;
//   none: no calendar at all: time values have no dates.
// Years are astronomical (year 0 is 1 BC, as in ISO 8601) in every calendar; reading a
// CF reference date in the standard and julian calendars, which have no year 0, is the
// job of cf_time.h.
#pragma once

#include <cstdint>
#include <string_view>

namespace strielad::geo {

enum class CfCalendar {
  kStandard,
  kProlepticGregorian,
  kJulian,
  kNoLeap,
  kAllLeap,
  k360Day,
  kNone,
};

// The calendar of a CF `calendar` attribute, case-insensitive; "" (no attribute) is
// standard, as CF says. "gregorian", "365_day" and "366_day" are the other names of
// standard, noleap and all_leap.
// \error kUnsupported naming `name` for a name CF does not define.
CfCalendar parse_cf_calendar(std::string_view name);

// The calendar's CF name ("standard", "proleptic_gregorian", ..., "none").
std::string_view cf_calendar_name(CfCalendar calendar) noexcept;

// Whether the calendar's days are real days (standard, proleptic_gregorian, julian), so
// that its dates are instants with a Julian day.
bool cf_calendar_is_real(CfCalendar calendar) noexcept;

struct CfDate {
  std::int64_t year = 1970;  // astronomical: 0 is 1 BC, -1 is 2 BC
  unsigned month = 1;        // 1..12
  unsigned day = 1;          // 1..31

  friend bool operator==(const CfDate&, const CfDate&) = default;
};

// Whether `date` is a day of the calendar (2001-02-29 is not, nor 1582-10-10 in the
// standard calendar, nor 2000-02-30 but in 360_day); never for kNone.
bool cf_date_exists(CfCalendar calendar, const CfDate& date) noexcept;

// Days from the calendar's 1970-01-01 to `date`. For the real calendars that is the same
// day, the Unix epoch (1970-01-01 of the Julian calendar is day 13), so their day
// numbers are comparable: the Julian day of the day's 00:00 is 2440587.5 + days.
// \error kInvalidArgument when the date is not a day of the calendar (cf_date_exists)
// or the calendar is kNone.
std::int64_t cf_day_number(CfCalendar calendar, const CfDate& date);

// The date of day number `days` (the inverse of cf_day_number).
// \error kInvalidArgument for kNone.
CfDate cf_date_of_day(CfCalendar calendar, std::int64_t days);

}  // namespace strielad::geo
