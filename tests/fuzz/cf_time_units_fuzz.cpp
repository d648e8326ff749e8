// SPDX-License-Identifier: Apache-2.0
// Fuzzes CF time units (lib/geo/cf_time.h) as they come from files' attributes: the
// first byte picks a calendar name, the rest is the units text. Parsing must succeed or
// throw strielad::Error; a parsed reference must give every value a date of the form
// [+-]YYYY-MM-DDThh:mm:ss[.mmm]Z or refuse it with strielad::Error (not finite, too far),
// and a value one day later must give a later day; anything else is a bug and aborts.
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "fuzz/fuzz_target.h"
#include "geo/cf_time.h"

using namespace strielad;

namespace {

std::vector<std::uint8_t> seed(char calendar, std::string_view units) {
  const std::string bytes = std::string(1, calendar) + std::string(units);
  return {bytes.begin(), bytes.end()};
}

bool is_digits(std::string_view s) {
  return !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos;
}

// [+-]YYYY-MM-DDThh:mm:ss[.mmm]Z
bool well_formed(const std::string& date) {
  std::string_view s(date);
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) s.remove_prefix(1);
  const auto t = s.find('T');
  if (t == std::string_view::npos || t < 10 || s.back() != 'Z') return false;
  const auto ymd = s.substr(0, t);
  const auto year_end = ymd.size() - 6;
  if (!is_digits(ymd.substr(0, year_end)) || ymd[year_end] != '-' || ymd[year_end + 3] != '-' ||
      !is_digits(ymd.substr(year_end + 1, 2)) || !is_digits(ymd.substr(year_end + 4, 2))) {
    return false;
  }
  const auto hms = s.substr(t + 1, s.size() - t - 2);
  if (hms.size() != 8 && hms.size() != 12) return false;
  return is_digits(hms.substr(0, 2)) && hms[2] == ':' && is_digits(hms.substr(3, 2)) &&
         hms[5] == ':' && is_digits(hms.substr(6, 2)) &&
         (hms.size() == 8 || (hms[8] == '.' && is_digits(hms.substr(9, 3))));
}

}  // namespace

std::vector<std::vector<std::uint8_t>> strielad_fuzz_seeds() {
  return {
      seed(0, "days since 1949-12-01 00:00:00"),
      seed(1, "hours since 1900-01-01"),
      seed(2, "seconds since 2013-04-26T12:00:00.5Z"),
      seed(3, "d since 1-1-1"),
      seed(4, "minutes since -4712-01-01 12:00 +1:00"),
      seed(5, "hrs since 1582-10-04 23:59:60 -0530"),
      seed(6, "months since 2000-01-01"),
      seed(7, "hours"),
  };
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const kCalendars[] = {"",       "standard", "proleptic_gregorian",
                                           "julian", "noleap",   "all_leap",
                                           "360_day", "none"};
  const std::string calendar = kCalendars[data[0] % 8];
  const std::string units(reinterpret_cast<const char*>(data + 1), size - 1);
  geo::CfTimeReference reference;
  try {
    reference = geo::parse_cf_time_reference(units, calendar);
  } catch (const Error&) {
    return 0;
  }
  for (const double value : {0.0, -1.0, 0.5, 1e-9, 123456.789, -987654.321, 1e7, -1e7, 3e8,
                             1e300, -1e300}) {
    std::string date, next;
    try {
      date = geo::cf_date_text(reference, value);
    } catch (const Error&) {
      continue;
    }
    if (!well_formed(date)) std::abort();
    // One day later is a later date (ISO 8601 text of non-negative years sorts by time).
    try {
      next = geo::cf_date_text(reference, value + 86400.0 / reference.seconds_per_unit);
    } catch (const Error&) {
      continue;
    }
    if (!well_formed(next)) std::abort();
    if (date[0] != '-' && next[0] != '-' && date[0] != '+' && next[0] != '+' && !(date < next)) {
      std::abort();
    }
  }
  return 0;
}
