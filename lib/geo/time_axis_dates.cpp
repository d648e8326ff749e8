// SPDX-License-Identifier: Apache-2.0
#include "geo/time_axis_dates.h"

#include "core/error.h"

namespace strielad::geo {

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
