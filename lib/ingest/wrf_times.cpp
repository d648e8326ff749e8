// SPDX-License-Identifier: Apache-2.0
#include "ingest/wrf_times.h"

#include <fmt/format.h>

#include <cctype>
#include <cstdint>
#include <optional>

#include "core/error.h"
#include "geo/cf_calendar.h"

namespace strielad::ingest {
namespace {

struct WrfInstant {
  geo::CfDate date;
  int hour = 0, minute = 0, second = 0;
};

// The digits of s[at, at + n) as a number; nullopt when one is not a digit.
std::optional<int> digits(std::string_view s, std::size_t at, std::size_t n) {
  int v = 0;
  for (std::size_t i = at; i < at + n; ++i) {
    if (!std::isdigit(static_cast<unsigned char>(s[i]))) return std::nullopt;
    v = v * 10 + (s[i] - '0');
  }
  return v;
}

std::string_view trimmed(const std::string& s) {
  std::string_view v(s);
  while (!v.empty() && (v.back() == '\0' || v.back() == ' ')) v.remove_suffix(1);
  return v;
}

std::optional<WrfInstant> parse(std::string_view s) {
  if (s.size() != 19 || s[4] != '-' || s[7] != '-' || (s[10] != '_' && s[10] != ' ') ||
      s[13] != ':' || s[16] != ':') {
    return std::nullopt;
  }
  const auto y = digits(s, 0, 4), mo = digits(s, 5, 2), d = digits(s, 8, 2), h = digits(s, 11, 2),
             mi = digits(s, 14, 2), se = digits(s, 17, 2);
  if (!y || !mo || !d || !h || !mi || !se) return std::nullopt;
  if (*mo < 1 || *mo > 12 || *d < 1 || *h > 23 || *mi > 59 || *se > 59) return std::nullopt;
  WrfInstant t;
  t.date = geo::CfDate{*y, static_cast<unsigned>(*mo), static_cast<unsigned>(*d)};
  if (!geo::cf_date_exists(geo::CfCalendar::kStandard, t.date)) return std::nullopt;
  t.hour = *h;
  t.minute = *mi;
  t.second = *se;
  return t;
}

std::int64_t seconds_of(const WrfInstant& t) {
  return geo::cf_day_number(geo::CfCalendar::kStandard, t.date) * 86400 +
         t.hour * 3600 + t.minute * 60 + t.second;
}

}  // namespace

TimeCoordinate wrf_time_coordinate(const std::vector<std::string>& times, std::string_view what) {
  TimeCoordinate tc;
  tc.name = "Time";
  tc.calendar = "standard";
  std::optional<WrfInstant> first;
  for (std::size_t s = 0; s < times.size(); ++s) {
    const std::string_view text = trimmed(times[s]);
    const auto t = parse(text);
    if (!t) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: Times of step {} is '{}', not a date YYYY-MM-DD_hh:mm:ss", what, s,
                       text);
    }
    if (!first) {
      first = t;
      tc.units = fmt::format("seconds since {:04d}-{:02d}-{:02d} {:02d}:{:02d}:{:02d}", t->date.year,
                             t->date.month, t->date.day, t->hour, t->minute, t->second);
    }
    tc.values.push_back(static_cast<double>(seconds_of(*t) - seconds_of(*first)));
    if (s > 0 && !(tc.values[s] > tc.values[s - 1])) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: Times of step {} ('{}') does not follow step {} ('{}')", what, s, text,
                       s - 1, trimmed(times[s - 1]));
    }
  }
  return tc;
}

}  // namespace strielad::ingest
