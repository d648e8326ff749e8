// SPDX-License-Identifier: Apache-2.0
#include "view/sun_direction.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "view/simulation_time.h"

namespace strielad::view {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// `lon` moved by whole turns into (reference - 180, reference + 180].
double near_longitude(double lon, double reference) {
  double d = std::fmod(lon - reference, 360.0);
  if (d <= -180) d += 360;
  if (d > 180) d -= 360;
  return reference + d;
}

std::string latitude_text(double lat) {
  return fmt::format("{:.2f} {}", std::fabs(lat), lat < 0 ? 'S' : 'N');
}
std::string longitude_text(double lon) {
  const double l = near_longitude(lon, 0.0);
  return fmt::format("{:.2f} {}", std::fabs(l), l < 0 ? 'W' : 'E');
}

SunAtTime seen_from(double julian_day, double lat, double lon) {
  SunAtTime sun;
  sun.position = geo::solar_position(julian_day, lat, lon);
  const auto& enu = sun.position.east_north_up;
  sun.direction = {enu[0], enu[1], enu[2]};
  sun.latitude_deg = lat;
  sun.longitude_deg = lon;
  return sun;
}

}  // namespace

double domain_longitude_span_deg(const lod::WorldFrame& frame) {
  if (!frame.on_earth()) return 0;
  const auto b = frame.geographic_bounds();
  return b.lon_hi - b.lon_lo;
}

SunAtTime sun_for_domain(double julian_day, double lon_lo, double lon_hi, double lat_lo,
                         double lat_hi, double lon0, double lat0) {
  const double span = lon_hi - lon_lo;
  if (!(span > kWideDomainLongitudeDeg)) {
    auto sun = seen_from(julian_day, lat0, lon0);
    sun.domain_longitude_span_deg = span;
    return sun;
  }
  // The sub-solar point: latitude the declination, longitude where the hour angle is 0
  // (it grows by one degree per degree east).
  const auto centre = geo::solar_position(julian_day, lat0, lon0);
  const double lat_s = centre.declination_deg;
  const double lon_s = near_longitude(lon0 - centre.hour_angle_deg, 0.5 * (lon_lo + lon_hi));
  // The sun is highest where the great-circle distance to the sub-solar point is least.
  // Within the longitudes: on the sub-solar meridian at the nearest latitude. Otherwise
  // on one of the two bounding meridians, where cos(distance) = sin(lat) sin(lat_s) +
  // cos(lat) cos(lat_s) cos(dlon) peaks at lat = atan2(sin lat_s, cos lat_s cos dlon);
  // the latitude limits are candidates too, and the highest sun of them all wins.
  std::vector<std::pair<double, double>> candidates;  // (lat, lon)
  if (lon_s >= lon_lo && lon_s <= lon_hi) {
    candidates.emplace_back(std::clamp(lat_s, lat_lo, lat_hi), lon_s);
  }
  for (const double lon : {lon_lo, lon_hi}) {
    const double dlon = (lon - lon_s) * kDeg;
    const double peak = std::atan2(std::sin(lat_s * kDeg), std::cos(lat_s * kDeg) * std::cos(dlon)) / kDeg;
    for (const double lat : {std::clamp(peak, lat_lo, lat_hi), lat_lo, lat_hi}) {
      candidates.emplace_back(lat, lon);
    }
  }
  SunAtTime best;
  bool first = true;
  for (const auto& [lat, lon] : candidates) {
    const auto sun = seen_from(julian_day, lat, lon);
    if (first || sun.position.elevation_deg > best.position.elevation_deg) best = sun;
    first = false;
  }
  best.viewpoint = SunViewpoint::kSunniestPoint;
  best.domain_longitude_span_deg = span;
  return best;
}

std::optional<SunAtTime> sun_at_step(const lod::WorldFrame& frame, const format::Manifest& manifest,
                                     std::uint32_t step, double seconds_after) {
  if (!frame.on_earth()) return std::nullopt;
  const auto jd = step_sun_julian_day(manifest, step, seconds_after);
  if (!jd) return std::nullopt;
  const auto b = frame.geographic_bounds();
  auto sun = sun_for_domain(*jd, b.lon_lo, b.lon_hi, std::max(b.lat_lo, -90.0),
                            std::min(b.lat_hi, 90.0), frame.lon0(), frame.lat0());
  if (frame.globe()) sun.direction = globe_sun_direction(*jd);
  return sun;
}

std::array<double, 2> subsolar_point(double julian_day) {
  const auto at_origin = geo::solar_position(julian_day, 0.0, 0.0);
  return {near_longitude(-at_origin.hour_angle_deg, 0.0), at_origin.declination_deg};
}

Vec3 globe_sun_direction(double julian_day) {
  const auto [lon, lat] = subsolar_point(julian_day);
  const double cl = std::cos(lat * kDeg);
  return {cl * std::cos(lon * kDeg), cl * std::sin(lon * kDeg), std::sin(lat * kDeg)};
}

std::string describe_sun(const SunAtTime& sun) {
  const std::string where = latitude_text(sun.latitude_deg) + ", " + longitude_text(sun.longitude_deg);
  if (sun.viewpoint == SunViewpoint::kDomainCentre) {
    return fmt::format("the true sun over the domain centre ({}), {:.1f} degrees up: the domain "
                       "spans {:.3g} degrees of longitude (at most {:g})",
                       where, sun.position.elevation_deg, sun.domain_longitude_span_deg,
                       kWideDomainLongitudeDeg);
  }
  return fmt::format("the sun over the domain's sunniest point ({}), {:.1f} degrees up: the "
                     "domain spans {:.3g} degrees of longitude (more than {:g})",
                     where, sun.position.elevation_deg, sun.domain_longitude_span_deg,
                     kWideDomainLongitudeDeg);
}

}  // namespace strielad::view
