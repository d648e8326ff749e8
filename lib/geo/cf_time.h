// SPDX-License-Identifier: Apache-2.0
// CF time coordinates (CF conventions, "Time coordinate"): units
// "<unit> since <date>[ <time>][ <zone>]" with unit seconds, minutes, hours or days (and
// the words udunits takes for them: s, sec, min, h, hr, hrs, d, ..., also milliseconds,
// microseconds and weeks), a date Y-M-D (unpadded too: "1-1-1"), an optional time
// h[:m[:s]] (fractional seconds allowed, separated by a space or 'T'), and an optional
// zone "Z", "UTC" or an offset like +01:00, +1:00 or -0530; values may be fractional and
// negative. Month and year units ("months since ...") are not a fixed length of time
// (CF discourages them) and give no dates.
// A reference date is a date of the axis's calendar (cf_calendar.h); in the standard
// and julian calendars year 0 does not exist and -1 is 1 BC (CF 1.9), while dates
// written by this file are ISO 8601 (astronomical years: 0000 is 1 BC).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "geo/cf_calendar.h"

namespace strielad::geo {

// Seconds per CF time unit word ("hours" -> 3600); nothing for other words.
std::optional<double> cf_unit_seconds(std::string_view unit);

// What the values of a CF time coordinate mean in its calendar.
struct CfTimeReference {
  CfCalendar calendar = CfCalendar::kStandard;
  double seconds_per_unit = 1;
  std::int64_t reference_day = 0;  // cf_day_number of the reference date
  double reference_seconds = 0;    // reference time of day, UTC (its zone applied: may be
                                   // negative or past 86400)
};

// \error kInvalidInput naming `units` when they are not "<unit> since <date>..." or the
// unit is unknown, or the date, time or zone is malformed or not one of the calendar;
// kUnsupported naming the unit for month and year units, and naming the calendar for a
// calendar CF does not define and for "none".
CfTimeReference parse_cf_time_reference(const std::string& units,
                                        const std::string& calendar = "");

// The date and time of coordinate value `value` in the reference's calendar, UTC, to
// the millisecond: ISO 8601 "YYYY-MM-DDThh:mm:ssZ", with ".mmm" before the Z when the
// milliseconds are not zero (1949-12-01 plus 20500.5 days: "2006-01-16T12:00:00Z").
// \error kInvalidArgument naming `value` when it is not finite or lies more than
// 3e13 seconds (some 950,000 years) from the reference.
std::string cf_date_text(const CfTimeReference& reference, double value);

// A CF time coordinate as instants.
struct CfTimeUnits {
  double seconds_per_unit = 1;
  double reference_julian_day = 0;  // the reference instant, UTC, as a Julian day
  // The instant of coordinate value `value`, UTC, as a Julian day.
  double julian_day(double value) const {
    return reference_julian_day + value * seconds_per_unit / 86400.0;
  }
};

// The errors of parse_cf_time_reference, and kUnsupported naming the calendar for the
// model calendars (noleap, 360_day, ...), whose dates are not real days.
CfTimeUnits parse_cf_time_units(const std::string& units, const std::string& calendar = "");

// The instant the sun is placed for at coordinate value `value`, UTC, as a Julian day.
// In the real calendars it is the value's own instant. A model calendar (noleap, all_leap,
// 360_day) has no real instants, so the sun keeps the model's season and time of day:
// the same year and time of day, on the day of the Gregorian year as far through its
// year as the model's day is through the model year (day d of a year of L days is day
// floor(d * G / L) of the Gregorian year of G days: 360_day's 30 Feb is 1 Mar, noleap's
// 1 Mar is 1 Mar in a common year and 29 Feb in a leap year).
// \error as parse_cf_time_reference (kUnsupported for calendar none), and as
// cf_date_text for a value too far from the reference.
double sun_julian_day(const CfTimeReference& reference, double value);

// ICON's (and CDO's) absolute time axis, units "day as %Y%m%d.%f": the value
// 20130426.5 is 2013-04-26 12:00:00 UTC in the proleptic Gregorian calendar.
bool is_absolute_day_units(std::string_view units);

// The units and calendar absolute day values become: a CF time axis of Unix seconds.
inline constexpr std::string_view kUnixSecondsUnits = "seconds since 1970-01-01 00:00:00";

// Seconds since 1970-01-01 00:00:00 UTC (proleptic Gregorian) of an absolute day value,
// the fraction of the day rounded to the millisecond.
// \error kInvalidInput naming `value` when it is not finite, its integer part is not a
// date YYYYMMDD of the proleptic Gregorian calendar, or it is negative.
double absolute_day_seconds(double value);

// A value of time axis `from` (units and calendar) in the units of `to`: the same
// instant, to the millisecond. Calendars must agree ("", standard and gregorian are one).
// \error kInvalidInput naming both calendars when they differ; kInvalidArgument naming
// `value` as cf_date_text does.
double convert_time_value(double value, const CfTimeReference& from, const CfTimeReference& to);

// The Julian day of a (proleptic) Gregorian UTC date and time (seconds may exceed 60:
// they carry).
double julian_day(int year, unsigned month, unsigned day, double seconds_of_day);

}  // namespace strielad::geo
