// SPDX-License-Identifier: Apache-2.0
#include "view/simulation_time.h"

#include "core/error.h"
#include "geo/cf_time.h"

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

}  // namespace strielad::view
