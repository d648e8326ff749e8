// SPDX-License-Identifier: Apache-2.0
#include "geo/cf_time.h"

#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>

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

}  // namespace

std::optional<double> cf_unit_seconds(std::string_view unit) {
  const std::string u = lower(unit);
  if (u == "seconds" || u == "second" || u == "s" || u == "sec" || u == "secs") return 1.0;
  if (u == "minutes" || u == "minute" || u == "min" || u == "mins") return 60.0;
  if (u == "hours" || u == "hour" || u == "h" || u == "hr" || u == "hrs") return 3600.0;
  if (u == "days" || u == "day" || u == "d") return 86400.0;
  return std::nullopt;
}

double julian_day(int year, unsigned month, unsigned day, double seconds_of_day) {
  using namespace std::chrono;
  const sys_days date{std::chrono::year{year} / std::chrono::month{month} / std::chrono::day{day}};
  const double days_since_1970 = static_cast<double>(date.time_since_epoch().count());
  return 2440587.5 + days_since_1970 + seconds_of_day / 86400.0;
}

CfTimeUnits parse_cf_time_units(const std::string& units, const std::string& calendar) {
  const std::string cal = lower(calendar);
  if (!cal.empty() && cal != "standard" && cal != "gregorian" && cal != "proleptic_gregorian") {
    throw make_error(ErrorCode::kUnsupported,
                     "time calendar '{}': only the Gregorian calendars (standard, gregorian, "
                     "proleptic_gregorian) map to real dates",
                     calendar);
  }
  const auto bad = [&](const char* what) {
    return make_error(ErrorCode::kInvalidInput,
                      "time units '{}': {} (expected '<unit> since YYYY-MM-DD[ hh:mm:ss][ zone]')",
                      units, what);
  };
  const std::string_view s(units);
  const auto since = lower(units).find(" since ");
  if (since == std::string::npos) throw bad("no ' since '");
  std::size_t unit_start = s.find_first_not_of(' ');
  const auto seconds = cf_unit_seconds(s.substr(unit_start, since - unit_start));
  if (!seconds) throw bad("unknown unit");
  std::size_t pos = since + 7;
  while (pos < s.size() && s[pos] == ' ') ++pos;

  double year = 0, month = 0, day = 0;
  const bool negative_year = expect_char(s, pos, '-');
  if (!read_number(s, pos, year) || !expect_char(s, pos, '-') || !read_number(s, pos, month) ||
      !expect_char(s, pos, '-') || !read_number(s, pos, day)) {
    throw bad("malformed date");
  }
  if (negative_year) year = -year;
  if (month < 1 || month > 12 || day < 1 || day > 31 || std::abs(year) > 100000) {
    throw bad("date out of range");
  }
  const std::chrono::year_month_day ymd{std::chrono::year{static_cast<int>(year)},
                                        std::chrono::month{static_cast<unsigned>(month)},
                                        std::chrono::day{static_cast<unsigned>(day)}};
  if (!ymd.ok()) throw bad("no such date");

  double hour = 0, minute = 0, second = 0;
  if (pos < s.size() && (s[pos] == ' ' || s[pos] == 'T' || s[pos] == 't')) {
    std::size_t p = pos + 1;
    while (p < s.size() && s[p] == ' ') ++p;
    if (p < s.size() && std::isdigit(static_cast<unsigned char>(s[p]))) {
      pos = p;
      if (!read_number(s, pos, hour)) throw bad("malformed time");
      if (expect_char(s, pos, ':')) {
        if (!read_number(s, pos, minute)) throw bad("malformed time");
        if (expect_char(s, pos, ':') && !read_number(s, pos, second, true)) {
          throw bad("malformed time");
        }
      }
      if (hour > 24 || minute > 59 || second >= 61) throw bad("time out of range");
    }
  }
  // Zone: Z, UTC/GMT, or +hh[:mm] / -hhmm; the offset is local minus UTC.
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
      if (!read_number(s, pos, hh)) throw bad("malformed zone");
      if (pos - digits_start == 4) {  // hhmm
        mm = std::fmod(hh, 100);
        hh = std::floor(hh / 100);
      } else if (expect_char(s, pos, ':') && !read_number(s, pos, mm)) {
        throw bad("malformed zone");
      }
      if (hh > 14 || mm > 59) throw bad("zone out of range");
      offset_seconds = sign * (hh * 3600 + mm * 60);
    }
    while (pos < s.size() && s[pos] == ' ') ++pos;
    if (pos != s.size()) throw bad("unexpected text after the date");
  }
  return CfTimeUnits{*seconds,
                     julian_day(static_cast<int>(year), static_cast<unsigned>(month),
                                static_cast<unsigned>(day),
                                hour * 3600 + minute * 60 + second - offset_seconds)};
}

}  // namespace strielad::geo
