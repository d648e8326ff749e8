// SPDX-License-Identifier: Apache-2.0
#include "ingest/time_reconciliation.h"

#include <cctype>

#include "core/error.h"

namespace strielad::ingest {

namespace {

std::string normalized_calendar(std::string_view calendar) {
  std::string c(calendar);
  for (char& ch : c) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (c.empty() || c == "gregorian") return "standard";
  return c;
}

std::optional<geo::CfTimeReference> parsed(const std::string& units, const std::string& calendar) {
  try {
    return geo::parse_cf_time_reference(units, calendar);
  } catch (const Error&) {
    return std::nullopt;
  }
}

}  // namespace

TimeUnitsReconciler::TimeUnitsReconciler(const TimeCoordinate& reference,
                                         std::string reference_what)
    : units_(reference.units),
      calendar_(reference.calendar),
      source_units_(reference.units),
      source_calendar_(reference.calendar),
      reference_what_(std::move(reference_what)) {
  if (geo::is_absolute_day_units(reference.units)) {
    units_ = std::string(geo::kUnixSecondsUnits);
    calendar_ = "proleptic_gregorian";
  }
  reference_ = parsed(units_, calendar_);
}

std::vector<double> TimeUnitsReconciler::values(const TimeCoordinate& time,
                                                std::string_view what) const {
  const bool absolute = geo::is_absolute_day_units(time.units);
  if (!absolute && time.units == source_units_ &&
      normalized_calendar(time.calendar) == normalized_calendar(source_calendar_) &&
      !geo::is_absolute_day_units(source_units_)) {
    return time.values;  // as written: no conversion
  }
  const auto refuse = [&](std::string_view why) {
    return make_error(ErrorCode::kInvalidInput,
                      "{}: time units '{}' (calendar '{}') cannot be merged with those of {}, "
                      "'{}' (calendar '{}'): {}",
                      what, time.units, time.calendar, reference_what_, source_units_,
                      source_calendar_, why);
  };
  if (!reference_) {
    throw refuse("those are not CF time units ('<unit> since <date>'), so the inputs must use "
                 "the same units and calendar");
  }
  std::optional<geo::CfTimeReference> from;
  if (absolute) {
    from = geo::parse_cf_time_reference(std::string(geo::kUnixSecondsUnits), "proleptic_gregorian");
  } else {
    from = parsed(time.units, time.calendar);
    if (!from) throw refuse("they are not CF time units ('<unit> since <date>')");
  }
  const bool same_calendar =
      from->calendar == reference_->calendar ||
      (absolute && normalized_calendar(calendar_) == "standard");  // Gregorian days either way
  if (!same_calendar) throw refuse("the calendars differ");
  std::vector<double> out;
  out.reserve(time.values.size());
  for (double v : time.values) {
    try {
      const double value = absolute ? geo::absolute_day_seconds(v) : v;
      geo::CfTimeReference source = *from;
      source.calendar = reference_->calendar;
      out.push_back(geo::convert_time_value(value, source, *reference_));
    } catch (const Error& e) {
      throw refuse(e.what());
    }
  }
  return out;
}

}  // namespace strielad::ingest
