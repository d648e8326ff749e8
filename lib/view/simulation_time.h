// SPDX-License-Identifier: Apache-2.0
// The real instant a view shows: a time step of the store (plus seconds within the
// step while advecting) as a UTC Julian day, from the CF time axis (geo/cf_time.h).
// The sun and the flight tracks both need it. And the time text the viewer's panel shows.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "format/manifest.h"

namespace strielad::view {

// Nothing when `step` is not a step of the store or the time axis has no real date
// (units not "<unit> since <date>", or a model calendar such as 360_day).
std::optional<double> step_julian_day(const format::Manifest& manifest, std::uint32_t step,
                                      double seconds_after = 0);

// The instant the sun is placed for at step `step` (plus `seconds_after`), UTC, as a
// Julian day: the step's instant in the real calendars; in a model calendar (noleap,
// all_leap, 360_day) the model's season and time of day on the Gregorian calendar
// (geo::sun_julian_day). Nothing when `step` is not a step of the store or the time
// axis has no dates (units not "<unit> since <date>", calendar none).
std::optional<double> step_sun_julian_day(const format::Manifest& manifest, std::uint32_t step,
                                          double seconds_after = 0);

// The panel's text for step `step`, two lines: the raw value with the axis's name and
// units ("time = 20500.5 days since 1949-12-01 00:00:00"), then its date in the store's
// calendar ("2006-01-16T12:00:00Z, proleptic_gregorian calendar") or why it has none
// ("no date: time units 'hours': no reference date ..."). Empty when `step` is not a
// step of the store.
std::string step_time_text(const format::Manifest& manifest, std::uint32_t step);

}  // namespace strielad::view
