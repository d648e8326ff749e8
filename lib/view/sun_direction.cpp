// SPDX-License-Identifier: Apache-2.0
#include "view/sun_direction.h"

#include "view/simulation_time.h"

namespace strielad::view {

std::optional<SunAtTime> sun_at_step(const lod::WorldFrame& frame, const format::Manifest& manifest,
                                     std::uint32_t step, double seconds_after) {
  if (frame.horizontal() != lod::HorizontalMap::kGeographic) return std::nullopt;
  const auto jd = step_julian_day(manifest, step, seconds_after);
  if (!jd) return std::nullopt;
  SunAtTime sun;
  sun.position = geo::solar_position(*jd, frame.origin(1), frame.origin(0));
  const auto& enu = sun.position.east_north_up;
  sun.direction = {enu[0], enu[1], enu[2]};
  return sun;
}

}  // namespace strielad::view
