// SPDX-License-Identifier: Apache-2.0
// The Gregorian and Julian day counts follow Howard Hinnant's "chrono-Compatible
// Low-Level Date Algorithms" (days_from_civil / civil_from_days): years counted from
// March, so that a leap day ends its year, in eras of 400 (Gregorian) or 4 (Julian)
// years.
#include "geo/cf_calendar.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <string>
#include <tuple>

#include "core/error.h"

namespace strielad::geo {
namespace {

constexpr std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  return a / b - ((a % b != 0) && ((a < 0) != (b < 0)));
}

// Day number (from 1970-01-01) of the first Gregorian day of the standard calendar,
// 1582-10-15; the day before it is the Julian 1582-10-04.
constexpr std::int64_t kFirstGregorianDay = -141427;
constexpr CfDate kFirstMissingDate{1582, 10, 5};  // after the Julian 1582-10-04
constexpr CfDate kFirstGregorianDate{1582, 10, 15};

bool before(const CfDate& a, const CfDate& b) {
  return std::tie(a.year, a.month, a.day) < std::tie(b.year, b.month, b.day);
}

bool gregorian_leap(std::int64_t y) { return y % 4 == 0 && (y % 100 != 0 || y % 400 == 0); }
bool julian_leap(std::int64_t y) { return y % 4 == 0; }

// Day of a March-based year (March 1st = 0) of month m, day d.
std::int64_t day_of_march_year(unsigned m, unsigned d) {
  return (153 * (m > 2 ? std::int64_t(m) - 3 : std::int64_t(m) + 9) + 2) / 5 + d - 1;
}

// Month and day of day `doy` of a March-based year.
void month_day_of_march_year(std::int64_t doy, unsigned& month, unsigned& day) {
  const std::int64_t mp = (5 * doy + 2) / 153;
  day = static_cast<unsigned>(doy - (153 * mp + 2) / 5 + 1);
  month = static_cast<unsigned>(mp < 10 ? mp + 3 : mp - 9);
}

std::int64_t gregorian_days(const CfDate& date) {
  const std::int64_t y = date.year - (date.month <= 2);
  const std::int64_t era = floor_div(y, 400);
  const std::int64_t yoe = y - era * 400;
  const std::int64_t doe =
      yoe * 365 + yoe / 4 - yoe / 100 + day_of_march_year(date.month, date.day);
  return era * 146097 + doe - 719468;
}

CfDate gregorian_date(std::int64_t days) {
  const std::int64_t z = days + 719468;
  const std::int64_t era = floor_div(z, 146097);
  const std::int64_t doe = z - era * 146097;
  const std::int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
  CfDate d;
  month_day_of_march_year(doe - (365 * yoe + yoe / 4 - yoe / 100), d.month, d.day);
  d.year = yoe + era * 400 + (d.month <= 2);
  return d;
}

// Julian calendar: eras of 4 March-based years, the last of which ends with February 29;
// 719470 puts the Julian 1970-01-01 (the Gregorian 1970-01-14) on day 13.
std::int64_t julian_days(const CfDate& date) {
  const std::int64_t y = date.year - (date.month <= 2);
  const std::int64_t era = floor_div(y, 4);
  const std::int64_t yoe = y - era * 4;
  return era * 1461 + yoe * 365 + day_of_march_year(date.month, date.day) - 719470;
}

CfDate julian_date(std::int64_t days) {
  const std::int64_t z = days + 719470;
  const std::int64_t era = floor_div(z, 1461);
  const std::int64_t doe = z - era * 1461;
  const std::int64_t yoe = std::min<std::int64_t>(doe / 365, 3);
  CfDate d;
  month_day_of_march_year(doe - 365 * yoe, d.month, d.day);
  d.year = yoe + era * 4 + (d.month <= 2);
  return d;
}

// Model calendars: every year the same length, months from a table.
constexpr std::array<std::int64_t, 13> kNoLeapStarts{0,   31,  59,  90,  120, 151, 181,
                                                     212, 243, 273, 304, 334, 365};
constexpr std::array<std::int64_t, 13> kAllLeapStarts{0,   31,  60,  91,  121, 152, 182,
                                                      213, 244, 274, 305, 335, 366};

std::int64_t fixed_year_days(const std::array<std::int64_t, 13>& starts, const CfDate& date) {
  return (date.year - 1970) * starts[12] + starts[date.month - 1] + date.day - 1;
}

CfDate fixed_year_date(const std::array<std::int64_t, 13>& starts, std::int64_t days) {
  const std::int64_t year = floor_div(days, starts[12]);
  const std::int64_t doy = days - year * starts[12];
  unsigned month = 1;
  while (doy >= starts[month]) ++month;
  return CfDate{1970 + year, month, static_cast<unsigned>(doy - starts[month - 1] + 1)};
}

unsigned days_in_month(CfCalendar calendar, std::int64_t year, unsigned month) {
  static constexpr std::array<unsigned, 12> kDays{31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const auto leap_february = [&](bool leap) { return month == 2 && leap ? 29u : kDays[month - 1]; };
  switch (calendar) {
    case CfCalendar::kStandard:
      return leap_february(year < 1582 ? julian_leap(year) : gregorian_leap(year));
    case CfCalendar::kProlepticGregorian: return leap_february(gregorian_leap(year));
    case CfCalendar::kJulian: return leap_february(julian_leap(year));
    case CfCalendar::kNoLeap: return kDays[month - 1];
    case CfCalendar::kAllLeap: return leap_february(true);
    case CfCalendar::k360Day: return 30;
    case CfCalendar::kNone: return 0;
  }
  return 0;
}

Error no_calendar() {
  return make_error(ErrorCode::kInvalidArgument, "calendar 'none' has no dates");
}

}  // namespace

CfCalendar parse_cf_calendar(std::string_view name) {
  std::string n;
  for (const char c : name) n += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (n.empty() || n == "standard" || n == "gregorian") return CfCalendar::kStandard;
  if (n == "proleptic_gregorian") return CfCalendar::kProlepticGregorian;
  if (n == "julian") return CfCalendar::kJulian;
  if (n == "noleap" || n == "365_day") return CfCalendar::kNoLeap;
  if (n == "all_leap" || n == "366_day") return CfCalendar::kAllLeap;
  if (n == "360_day") return CfCalendar::k360Day;
  if (n == "none") return CfCalendar::kNone;
  throw make_error(ErrorCode::kUnsupported,
                   "calendar '{}' is not a CF calendar (standard, gregorian, proleptic_gregorian, "
                   "julian, noleap, 365_day, all_leap, 366_day, 360_day, none)",
                   name);
}

std::string_view cf_calendar_name(CfCalendar calendar) noexcept {
  switch (calendar) {
    case CfCalendar::kStandard: return "standard";
    case CfCalendar::kProlepticGregorian: return "proleptic_gregorian";
    case CfCalendar::kJulian: return "julian";
    case CfCalendar::kNoLeap: return "noleap";
    case CfCalendar::kAllLeap: return "all_leap";
    case CfCalendar::k360Day: return "360_day";
    case CfCalendar::kNone: return "none";
  }
  return "?";
}

bool cf_calendar_is_real(CfCalendar calendar) noexcept {
  return calendar == CfCalendar::kStandard || calendar == CfCalendar::kProlepticGregorian ||
         calendar == CfCalendar::kJulian;
}

bool cf_date_exists(CfCalendar calendar, const CfDate& date) noexcept {
  if (calendar == CfCalendar::kNone || date.month < 1 || date.month > 12 || date.day < 1) {
    return false;
  }
  if (date.day > days_in_month(calendar, date.year, date.month)) return false;
  return calendar != CfCalendar::kStandard || before(date, kFirstMissingDate) ||
         !before(date, kFirstGregorianDate);
}

std::int64_t cf_day_number(CfCalendar calendar, const CfDate& date) {
  if (calendar == CfCalendar::kNone) throw no_calendar();
  if (!cf_date_exists(calendar, date)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "{:04}-{:02}-{:02} is not a day of the {} calendar", date.year, date.month,
                     date.day, cf_calendar_name(calendar));
  }
  switch (calendar) {
    case CfCalendar::kStandard:
      return before(date, kFirstGregorianDate) ? julian_days(date) : gregorian_days(date);
    case CfCalendar::kProlepticGregorian: return gregorian_days(date);
    case CfCalendar::kJulian: return julian_days(date);
    case CfCalendar::kNoLeap: return fixed_year_days(kNoLeapStarts, date);
    case CfCalendar::kAllLeap: return fixed_year_days(kAllLeapStarts, date);
    case CfCalendar::k360Day:
      return (date.year - 1970) * 360 + (date.month - 1) * 30 + date.day - 1;
    case CfCalendar::kNone: break;
  }
  throw no_calendar();
}

CfDate cf_date_of_day(CfCalendar calendar, std::int64_t days) {
  switch (calendar) {
    case CfCalendar::kStandard:
      return days < kFirstGregorianDay ? julian_date(days) : gregorian_date(days);
    case CfCalendar::kProlepticGregorian: return gregorian_date(days);
    case CfCalendar::kJulian: return julian_date(days);
    case CfCalendar::kNoLeap: return fixed_year_date(kNoLeapStarts, days);
    case CfCalendar::kAllLeap: return fixed_year_date(kAllLeapStarts, days);
    case CfCalendar::k360Day: {
      const std::int64_t year = floor_div(days, 360);
      const std::int64_t doy = days - year * 360;
      return CfDate{1970 + year, static_cast<unsigned>(doy / 30 + 1),
                    static_cast<unsigned>(doy % 30 + 1)};
    }
    case CfCalendar::kNone: break;
  }
  throw no_calendar();
}

}  // namespace strielad::geo
