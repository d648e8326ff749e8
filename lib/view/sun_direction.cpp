// SPDX-License-Identifier: Apache-2.0
#include "view/sun_direction.h"

#include "core/error.h"
#include "geo/cf_time.h"

namespace strielad::view {

std::optional<SunAtTime> sun_at_step(const lod::WorldFrame& frame, const format::Manifest& manifest,
                                     std::uint32_t step, double seconds_after) {
  if (frame.horizontal() != lod::HorizontalMap::kGeographic) return std::nullopt;
  if (step >= manifest.time.values.size()) return std::nullopt;
  geo::CfTimeUnits units;
  try {
    units = geo::parse_cf_time_units(manifest.time.units, manifest.time.calendar);
  } catch (const Error&) {
    return std::nullopt;
  }
  const double jd = units.julian_day(manifest.time.values[step]) + seconds_after / 86400.0;
  SunAtTime sun;
  sun.position = geo::solar_position(jd, frame.origin(1), frame.origin(0));
  const auto& enu = sun.position.east_north_up;
  sun.direction = {enu[0], enu[1], enu[2]};
  return sun;
}

}  // namespace strielad::view
