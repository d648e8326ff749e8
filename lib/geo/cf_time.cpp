// SPDX-License-Identifier: Apache-2.0
#include "geo/cf_time.h"
#include "geo/time_axis_dates.h"

#include <cctype>
#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "core/error.h"

namespace strielad::geo {
namespace {

std::string lower(std::string_view s) {
  std::string out;
  for (const char c : s) out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Reads digits (and for `fraction` a decimal part) at s[pos]; false when none.
bool read_number(std::string_view s, std::size_t& pos, double& value, bool fraction = false) {
  const std::size_t start = pos;
  while (pos < s.size() && (std::isdigit(static_cast<unsigned char>(s[pos])) ||
                            (fraction && s[pos] == '.'))) {
    ++pos;
  }
  if (pos == start) return false;
  const auto text = s.substr(start, pos - start);
  const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  return r.ec == std::errc() && r.ptr == text.data() + text.size();
}

bool expect_char(std::string_view s, std::size_t& pos, char c) {
  if (pos < s.size() && s[pos] == c) {
    ++pos;
    return true;
  }
  return false;
}

bool is_month_or_year_unit(std::string_view unit) {
  const std::string u = lower(unit);
  for (const char* w : {"month", "months", "mon", "mons", "year", "years", "yr", "yrs",
                        "common_year", "common_years", "leap_year", "leap_years"}) {
    if (u == w) return true;
  }
  return false;
}

// Largest distance from the reference that cf_date_text writes a date for, in seconds
// (some 950,000 years: six-digit years at most).
constexpr double kMaxDateSeconds = 3e13;

// Seconds from the reference of coordinate value `value`. \error kInvalidArgument naming
// `value` when they are not finite or more than kMaxDateSeconds.
double checked_offset_seconds(double value, double seconds_per_unit) {
  const double offset = value * seconds_per_unit;
  if (!std::isfinite(offset) || std::abs(offset) > kMaxDateSeconds) {
    throw make_error(ErrorCode::kInvalidArgument, "time value {} is {} for a date", value,
                     std::isfinite(offset) ? "too far from the reference date" : "not finite");
  }
  return offset;
}

std::string year_text(std::int64_t year) {
  if (year < 0) return fmt::format("-{:04}", -year);
  if (year > 9999) return fmt::format("+{}", year);
  return fmt::format("{:04}", year);
}

}  // namespace

std::optional<double> cf_unit_seconds(std::string_view unit) {
  const std::string u = lower(unit);
  if (u == "seconds" || u == "second" || u == "s" || u == "sec" || u == "secs") return 1.0;
  if (u == "minutes" || u == "minute" || u == "min" || u == "mins") return 60.0;
  if (u == "hours" || u == "hour" || u == "h" || u == "hr" || u == "hrs") return 3600.0;
  if (u == "days" || u == "day" || u == "d") return 86400.0;
  if (u == "weeks" || u == "week") return 7 * 86400.0;
  if (u == "milliseconds" || u == "millisecond" || u == "ms" || u == "msec" || u == "msecs") {
    return 1e-3;
  }
  if (u == "microseconds" || u == "microsecond" || u == "us" || u == "usec" || u == "usecs") {
    return 1e-6;
  }
  return std::nullopt;
}

namespace {

Error malformed_units(const std::string& units, const std::string& what) {
  return make_error(ErrorCode::kInvalidInput,
                    "time units '{}': {} (CF time units are '<unit> since YYYY-MM-DD[ "
                    "hh:mm:ss][ zone]')",
                    units, what);
}

// Seconds per unit of `units`, whose unit ends where " since " begins (at `since`).
double unit_seconds(const std::string& units, std::size_t since) {
  const std::string_view s(units);
  const std::size_t unit_start = s.find_first_not_of(' ');
  const std::string_view unit = s.substr(unit_start, since - unit_start);
  if (is_month_or_year_unit(unit)) {
    throw make_error(ErrorCode::kUnsupported,
                     "time units '{}': months and years are not a fixed length of time (CF "
                     "discourages them), so the values have no exact dates",
                     units);
  }
  const auto seconds = cf_unit_seconds(unit);
  if (!seconds) throw malformed_units(units, fmt::format("unknown unit '{}'", unit));
  return *seconds;
}

// The reference date YYYY-MM-DD at `pos`, which must exist in calendar `cal`.
CfDate read_reference_date(const std::string& units, std::size_t& pos, CfCalendar cal) {
  const std::string_view s(units);
  double year = 0, month = 0, day = 0;
  const bool negative_year = expect_char(s, pos, '-');
  if (!read_number(s, pos, year) || !expect_char(s, pos, '-') || !read_number(s, pos, month) ||
      !expect_char(s, pos, '-') || !read_number(s, pos, day)) {
    throw malformed_units(units, "malformed date");
  }
  if (month < 1 || month > 12 || day < 1 || day > 31 || year > 100000) {
    throw malformed_units(units, "date out of range");
  }
  // The standard and julian calendars count years historically: no year 0, -1 is 1 BC.
  const bool historical_years = cal == CfCalendar::kStandard || cal == CfCalendar::kJulian;
  if (historical_years && year == 0) {
    throw malformed_units(units,
                          fmt::format("year 0 does not exist in the {} calendar (1 BC is year -1)",
                                      cf_calendar_name(cal)));
  }
  const CfDate date{static_cast<std::int64_t>(negative_year ? (historical_years ? 1 - year : -year)
                                                            : year),
                    static_cast<unsigned>(month), static_cast<unsigned>(day)};
  if (!cf_date_exists(cal, date)) {
    throw malformed_units(units, fmt::format("no such date in the {} calendar", cf_calendar_name(cal)));
  }
  return date;
}

// The optional time of day hh[:mm[:ss]] at `pos`, in seconds.
double read_time_of_day(const std::string& units, std::size_t& pos) {
  const std::string_view s(units);
  double hour = 0, minute = 0, second = 0;
  if (pos < s.size() && (s[pos] == ' ' || s[pos] == 'T' || s[pos] == 't')) {
    std::size_t p = pos + 1;
    while (p < s.size() && s[p] == ' ') ++p;
    if (p < s.size() && std::isdigit(static_cast<unsigned char>(s[p]))) {
      pos = p;
      if (!read_number(s, pos, hour)) throw malformed_units(units, "malformed time");
      if (expect_char(s, pos, ':')) {
        if (!read_number(s, pos, minute)) throw malformed_units(units, "malformed time");
        if (expect_char(s, pos, ':') && !read_number(s, pos, second, true)) {
          throw malformed_units(units, "malformed time");
        }
      }
      if (hour > 24 || minute > 59 || second >= 61) throw malformed_units(units, "time out of range");
    }
  }
  return hour * 3600 + minute * 60 + second;
}

// The optional zone at `pos`, which ends the units: Z, UTC/GMT, or +hh[:mm] / -hhmm.
// Returns the offset, local minus UTC, in seconds.
double read_zone_offset(const std::string& units, std::size_t& pos) {
  const std::string_view s(units);
  double offset_seconds = 0;
  while (pos < s.size() && s[pos] == ' ') ++pos;
  if (pos < s.size()) {
    const std::string rest = lower(s.substr(pos));
    if (rest == "z" || rest == "utc" || rest == "gmt") {
      pos = s.size();
    } else if (s[pos] == '+' || s[pos] == '-') {
      const double sign = s[pos] == '-' ? -1 : 1;
      ++pos;
      const std::size_t digits_start = pos;
      double hh = 0, mm = 0;
      if (!read_number(s, pos, hh)) throw malformed_units(units, "malformed zone");
      if (pos - digits_start == 4) {  // hhmm
        mm = std::fmod(hh, 100);
        hh = std::floor(hh / 100);
      } else if (expect_char(s, pos, ':') && !read_number(s, pos, mm)) {
        throw malformed_units(units, "malformed zone");
      }
      if (hh > 14 || mm > 59) throw malformed_units(units, "zone out of range");
      offset_seconds = sign * (hh * 3600 + mm * 60);
    }
    while (pos < s.size() && s[pos] == ' ') ++pos;
    if (pos != s.size()) throw malformed_units(units, "unexpected text after the date");
  }
  return offset_seconds;
}

}  // namespace

CfTimeReference parse_cf_time_reference(const std::string& units, const std::string& calendar) {
  const CfCalendar cal = parse_cf_calendar(calendar);
  if (cal == CfCalendar::kNone) {
    throw make_error(ErrorCode::kUnsupported,
                     "calendar 'none': the time axis has no calendar, so its values have no dates");
  }
  const std::string_view s(units);
  if (s.find_first_not_of(' ') == std::string_view::npos) {
    throw make_error(ErrorCode::kInvalidInput,
                     "the time axis has no units, so its values have no dates");
  }
  const auto since = lower(units).find(" since ");
  if (since == std::string::npos) throw malformed_units(units, "no reference date");
  const double seconds = unit_seconds(units, since);
  std::size_t pos = since + 7;
  while (pos < s.size() && s[pos] == ' ') ++pos;
  const CfDate date = read_reference_date(units, pos, cal);
  const double time_of_day = read_time_of_day(units, pos);
  const double offset_seconds = read_zone_offset(units, pos);
  return CfTimeReference{cal, seconds, cf_day_number(cal, date), time_of_day - offset_seconds};
}

std::string cf_date_text(const CfTimeReference& reference, double value) {
  const double offset = checked_offset_seconds(value, reference.seconds_per_unit);
  constexpr std::int64_t kMsPerDay = 86'400'000;
  const std::int64_t ms =
      std::llround(offset * 1000.0) + std::llround(reference.reference_seconds * 1000.0);
  const std::int64_t days = ms / kMsPerDay - (ms % kMsPerDay < 0);
  const std::int64_t of_day = ms - days * kMsPerDay;
  const CfDate d = cf_date_of_day(reference.calendar, reference.reference_day + days);
  const std::int64_t s = of_day / 1000;
  std::string text = fmt::format("{}-{:02}-{:02}T{:02}:{:02}:{:02}", year_text(d.year), d.month,
                                 d.day, s / 3600, s / 60 % 60, s % 60);
  if (of_day % 1000 != 0) text += fmt::format(".{:03}", of_day % 1000);
  return text + "Z";
}

CfTimeUnits parse_cf_time_units(const std::string& units, const std::string& calendar) {
  const CfTimeReference r = parse_cf_time_reference(units, calendar);
  if (!cf_calendar_is_real(r.calendar)) {
    throw make_error(ErrorCode::kUnsupported,
                     "time calendar '{}': only the standard, proleptic_gregorian and julian "
                     "calendars map to real dates",
                     calendar);
  }
  const double days = static_cast<double>(r.reference_day) + r.reference_seconds / 86400.0;
  return CfTimeUnits{r.seconds_per_unit, 2440587.5 + days};
}

double sun_julian_day(const CfTimeReference& reference, double value) {
  const double offset = checked_offset_seconds(value, reference.seconds_per_unit);
  const double total = offset + reference.reference_seconds;  // from the reference day's 00:00
  const double whole_days = std::floor(total / 86400.0);
  const double of_day = total - whole_days * 86400.0;
  const std::int64_t day = reference.reference_day + static_cast<std::int64_t>(whole_days);
  if (cf_calendar_is_real(reference.calendar)) {
    return 2440587.5 + static_cast<double>(day) + of_day / 86400.0;
  }
  const CfCalendar c = reference.calendar;
  const CfDate date = cf_date_of_day(c, day);
  const std::int64_t year_start = cf_day_number(c, CfDate{date.year, 1, 1});
  const std::int64_t model_length = cf_day_number(c, CfDate{date.year + 1, 1, 1}) - year_start;
  const CfCalendar g = CfCalendar::kProlepticGregorian;
  const std::int64_t gregorian_start = cf_day_number(g, CfDate{date.year, 1, 1});
  const std::int64_t gregorian_length = cf_day_number(g, CfDate{date.year + 1, 1, 1}) - gregorian_start;
  const std::int64_t gregorian_day = (day - year_start) * gregorian_length / model_length;
  return 2440587.5 + static_cast<double>(gregorian_start + gregorian_day) + of_day / 86400.0;
}

bool is_absolute_day_units(std::string_view units) {
  std::string u;
  for (char c : units) u += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  while (!u.empty() && u.back() == ' ') u.pop_back();
  return u == "day as %y%m%d.%f" || u == "days as %y%m%d.%f";
}

double absolute_day_seconds(double value) {
  const double whole = std::floor(value);
  const auto bad = [&](std::string_view why) {
    return make_error(ErrorCode::kInvalidInput,
                      "absolute time value {} (units 'day as %Y%m%d.%f'): {}", value, why);
  };
  if (!std::isfinite(value) || value < 0 || whole > 99999999) throw bad("not a date YYYYMMDD");
  const auto ymd = static_cast<std::int64_t>(whole);
  const CfDate date{ymd / 10000, static_cast<unsigned>(ymd / 100 % 100),
                    static_cast<unsigned>(ymd % 100)};
  if (!cf_date_exists(CfCalendar::kProlepticGregorian, date)) {
    throw bad("its integer part is not a date YYYYMMDD");
  }
  const std::int64_t day = cf_day_number(CfCalendar::kProlepticGregorian, date);
  const double ms = std::round((value - whole) * 86'400'000.0);
  return static_cast<double>(day) * 86400.0 + ms / 1000.0;
}

double convert_time_value(double value, const CfTimeReference& from, const CfTimeReference& to) {
  if (from.calendar != to.calendar) {
    throw make_error(ErrorCode::kInvalidInput,
                     "time in calendar '{}' cannot be expressed in calendar '{}'",
                     cf_calendar_name(from.calendar), cf_calendar_name(to.calendar));
  }
  const double offset = checked_offset_seconds(value, from.seconds_per_unit);
  // Seconds from `to`'s reference instant, to the millisecond.
  const double seconds = static_cast<double>(from.reference_day - to.reference_day) * 86400.0 +
                         (from.reference_seconds - to.reference_seconds) + offset;
  const double ms = std::round(seconds * 1000.0);
  return ms / 1000.0 / to.seconds_per_unit;
}

double julian_day(int year, unsigned month, unsigned day, double seconds_of_day) {
  const auto days = cf_day_number(CfCalendar::kProlepticGregorian, CfDate{year, month, day});
  return 2440587.5 + static_cast<double>(days) + seconds_of_day / 86400.0;
}

TimeAxisDates::TimeAxisDates(const TimeAxis& axis) {
  try {
    reference_ = parse_cf_time_reference(axis.units, axis.calendar);
  } catch (const Error& e) {
    why_not_ = e.what();
  }
}

TimeDate TimeAxisDates::date(double value) const {
  if (!reference_) return TimeDate{"", why_not_};
  try {
    return TimeDate{cf_date_text(*reference_, value), ""};
  } catch (const Error& e) {
    return TimeDate{"", e.what()};
  }
}

nlohmann::json time_step_json(const TimeAxis& axis, std::uint32_t step) {
  if (step >= axis.values.size()) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "time step {} is not a step of the time axis ({} steps)", step,
                     axis.values.size());
  }
  const double value = axis.values[step];
  const TimeDate date = TimeAxisDates(axis).date(value);
  nlohmann::json j{{"step", step},
                   {"value", value},
                   {"units", axis.units},
                   {"calendar", axis.calendar},
                   {"date", date.ok() ? nlohmann::json(date.text) : nlohmann::json()}};
  if (!date.ok()) j["date_error"] = date.why_not;
  return j;
}

}  // namespace strielad::geo
