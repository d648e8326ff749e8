// SPDX-License-Identifier: Apache-2.0
// One set of time units for every input of a conversion: the first input's. A time step
// spread over files written in other units ("hours since" another date, days instead of
// hours) is the same instant expressed in the reference units (to the millisecond);
// ICON's absolute time axis "day as %Y%m%d.%f" becomes seconds since 1970-01-01 00:00:00
// in the proleptic Gregorian calendar (geo/cf_time.h). Calendars must agree: a date of
// one calendar is not a date of another ("", standard and gregorian are one).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geo/cf_time.h"
#include "ingest/file_scan.h"

namespace strielad::ingest {

class TimeUnitsReconciler {
 public:
  // `reference`: the first input's time coordinate. Units that are not CF time units
  // ("<unit> since <date>") are kept as they are, and then only inputs in exactly those
  // units and calendar can be merged.
  // `reference_what` names its file and variable in errors.
  TimeUnitsReconciler(const TimeCoordinate& reference, std::string reference_what);

  // The catalog's time units and calendar.
  const std::string& units() const { return units_; }
  const std::string& calendar() const { return calendar_; }

  // `time`'s values in the catalog's units. `what` names the file and variable.
  // \error kInvalidInput naming `what`, both units and both calendars when the values
  // cannot be expressed in the reference units (different calendars, units that are not
  // CF time units, a bad absolute date).
  std::vector<double> values(const TimeCoordinate& time, std::string_view what) const;

 private:
  std::string units_, calendar_;
  std::string source_units_, source_calendar_;  // the reference as written
  std::string reference_what_;
  std::optional<geo::CfTimeReference> reference_;  // units_ parsed, when CF time units
};

}  // namespace strielad::ingest
