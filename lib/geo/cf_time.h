// SPDX-License-Identifier: Apache-2.0
// CF time coordinates as instants (CF conventions, "Time coordinate"): units
// "<unit> since <date>[ <time>][ <zone>]" with unit seconds, minutes, hours or days
// (and their abbreviations s, sec, min, h, d), a date Y-M-D, an optional time h:m:s
// (fractional seconds allowed, separated by a space or 'T'), and an optional zone "Z",
// "UTC" or an offset like +01:00 / -0530. Calendars "standard", "gregorian",
// "proleptic_gregorian" (or none) are the Gregorian calendar; the model calendars
// ("noleap", "360_day", ...) have no fixed map to real dates and are refused.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace strielad::geo {

// Seconds per CF time unit word ("hours" -> 3600); nothing for other words.
std::optional<double> cf_unit_seconds(std::string_view unit);

struct CfTimeUnits {
  double seconds_per_unit = 1;
  double reference_julian_day = 0;  // the reference instant, UTC, as a Julian day
  // The instant of coordinate value `value`, UTC, as a Julian day.
  double julian_day(double value) const {
    return reference_julian_day + value * seconds_per_unit / 86400.0;
  }
};

// \error kInvalidInput naming `units` when it is not "<unit> since <date>..." or the
// date, time or zone is malformed or out of range; kUnsupported naming the calendar
// for calendars other than the Gregorian ones.
CfTimeUnits parse_cf_time_units(const std::string& units, const std::string& calendar = "");

// The Julian day of a Gregorian UTC date and time (seconds may exceed 60: they carry).
double julian_day(int year, unsigned month, unsigned day, double seconds_of_day);

}  // namespace strielad::geo
