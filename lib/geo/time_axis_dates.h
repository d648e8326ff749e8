// SPDX-License-Identifier: Apache-2.0
// Dates beside raw time values, for what the tools print (strielad-convert info, the
// --json outputs, the viewer's panel): the ISO 8601 date of each value of a store's time
// axis in its calendar (cf_time.h), or the one reason the axis has none ("time units
// 'hours': no reference date ..."), so that no tool prints a wrong date silently.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>

#include "geo/cf_time.h"
#include "grid/axis.h"

namespace strielad::geo {

// A date, or why there is none.
struct TimeDate {
  std::string text;     // "2006-01-16T12:00:00Z"; empty when there is no date
  std::string why_not;  // empty when there is a date

  bool ok() const { return why_not.empty(); }
};

class TimeAxisDates {
 public:
  // Never throws: units or a calendar that give no dates are kept as the reason.
  explicit TimeAxisDates(const TimeAxis& axis);

  // Empty when the axis has dates; else why none of its values has one.
  const std::string& why_not() const { return why_not_; }
  bool has_dates() const { return reference_.has_value(); }

  // The date of a value of this axis (a value may have none: not finite, too far).
  TimeDate date(double value) const;

 private:
  std::optional<CfTimeReference> reference_;
  std::string why_not_;
};

// A time step for --json outputs: {"step": 3, "value": 18, "units": "hours since ...",
// "calendar": "standard", "date": "2001-01-01T18:00:00Z"}; when the step has no date,
// "date" is null and "date_error" says why. "calendar" is "" when the axis names none.
// \error kInvalidArgument when `step` is not a step of the axis.
nlohmann::json time_step_json(const TimeAxis& axis, std::uint32_t step);

}  // namespace strielad::geo
