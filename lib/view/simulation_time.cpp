// SPDX-License-Identifier: Apache-2.0
#include "view/simulation_time.h"

#include <fmt/format.h>

#include "core/error.h"
#include "geo/cf_time.h"
#include "geo/time_axis_dates.h"

namespace strielad::view {

std::optional<double> step_julian_day(const format::Manifest& manifest, std::uint32_t step,
                                      double seconds_after) {
  if (step >= manifest.time.values.size()) return std::nullopt;
  try {
    const auto units = geo::parse_cf_time_units(manifest.time.units, manifest.time.calendar);
    return units.julian_day(manifest.time.values[step]) + seconds_after / 86400.0;
  } catch (const Error&) {
    return std::nullopt;
  }
}

std::optional<double> step_sun_julian_day(const format::Manifest& manifest, std::uint32_t step,
                                          double seconds_after) {
  if (step >= manifest.time.values.size()) return std::nullopt;
  try {
    const auto reference = geo::parse_cf_time_reference(manifest.time.units, manifest.time.calendar);
    return geo::sun_julian_day(reference, manifest.time.values[step]) + seconds_after / 86400.0;
  } catch (const Error&) {
    return std::nullopt;
  }
}

std::string step_time_text(const format::Manifest& manifest, std::uint32_t step) {
  const TimeAxis& t = manifest.time;
  if (step >= t.values.size()) return "";
  const double value = t.values[step];
  std::string text = fmt::format("{} = {}{}{}", t.name.empty() ? "time" : t.name, value,
                                 t.units.empty() ? "" : " ", t.units);
  const geo::TimeDate date = geo::TimeAxisDates(t).date(value);
  if (date.ok()) {
    return text + fmt::format("\n{}, {} calendar", date.text,
                              t.calendar.empty() ? "standard" : t.calendar);
  }
  return text + "\nno date: " + date.why_not;
}

}  // namespace strielad::view
