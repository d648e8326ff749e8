// SPDX-License-Identifier: Apache-2.0
#include "view/globe_view.h"

#include <cmath>

#include "view/simulation_time.h"
#include "view/sun_direction.h"

namespace strielad::view {

std::array<double, 2> globe_home_point(const lod::WorldFrame& frame,
                                       const format::Manifest& manifest, std::uint32_t step) {
  const std::array<double, 2> centre{frame.lon0(), frame.lat0()};
  const auto b = frame.geographic_bounds();
  if (b.lon_hi - b.lon_lo < 180.0) return centre;
  const auto jd = step_sun_julian_day(manifest, step);
  if (!jd) return centre;
  return subsolar_point(*jd);
}

OrbitCamera home_orbit_camera(const lod::WorldFrame& frame, const format::Manifest& manifest,
                              std::uint32_t step) {
  OrbitCamera camera(frame.domain());
  if (frame.globe()) {
    const auto [lon, lat] = globe_home_point(frame, manifest, step);
    camera.set_globe(lon, lat);
  }
  return camera;
}

}  // namespace strielad::view
