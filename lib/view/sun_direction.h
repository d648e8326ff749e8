// SPDX-License-Identifier: Apache-2.0
// The sun the viewer lights with, also for domains wide in longitude: the true
// direction towards the sun (geo/solar_position.h) at the simulation time, in the
// viewer's world frame (x east, y north, z up: the local east-north-up frame, which the
// world frame's map takes as the same everywhere). One direction lights the whole
// domain, seen from one point of it:
// - a domain spanning at most kWideDomainLongitudeDeg of longitude: its centre. At night
//   the sun points below the horizon, as it should: the user shaders decide what night
//   looks like.
// - a wider domain: its sunniest point, where the sun stands highest (the sub-solar
//   point when the domain holds it, so the sun is then straight overhead). Across 30
//   degrees of longitude the local solar time differs by two hours, so one direction
//   cannot be true everywhere; over a global domain the centre's sun is as often below
//   the horizon as not, and the picture would be night although half of it is day. The
//   sunniest point lights the picture as its day side is lit. A wide domain is dark only
//   when every point of it has the sun below the horizon.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "format/manifest.h"
#include "geo/solar_position.h"
#include "lod/geometry.h"
#include "lod/world_frame.h"

namespace strielad::view {

// Domains wider than this (degrees of longitude) are lit from their sunniest point.
inline constexpr double kWideDomainLongitudeDeg = 30.0;

enum class SunViewpoint { kDomainCentre, kSunniestPoint };

struct SunAtTime {
  Vec3 direction{};  // unit, world frame
  geo::SolarPosition position;  // seen from (latitude_deg, longitude_deg)
  SunViewpoint viewpoint = SunViewpoint::kDomainCentre;
  double latitude_deg = 0, longitude_deg = 0;  // where the sun is seen from
  double domain_longitude_span_deg = 0;
};

// Degrees of true longitude a frame's domain spans (its geographic_bounds; 0 for a
// frame without a place on the Earth).
double domain_longitude_span_deg(const lod::WorldFrame& frame);

// The sun at time step `step` plus `seconds_after` seconds, seen from the point the
// rule above picks, by true longitude and latitude (through the grid mapping on a
// mapped frame). Nothing when the frame has no place on the Earth (a Cartesian grid:
// WorldFrame::no_earth_reason) or the time axis has no date (units not "<unit> since
// <date>", calendar none). A model calendar (360_day, ...) keeps the model's season and
// time of day (step_sun_julian_day).
// On the globe the direction is globe_sun_direction (the rest describes the sunniest
// point as above).
std::optional<SunAtTime> sun_at_step(const lod::WorldFrame& frame, const format::Manifest& manifest,
                                     std::uint32_t step, double seconds_after = 0);

// The sub-solar point at `julian_day` (UTC): {longitude in (-180, 180], latitude}
// (degrees), where the sun stands in the zenith.
std::array<double, 2> subsolar_point(double julian_day);
// The direction towards the sun in the globe's frame (WGS84 ECEF, lod/world_frame.h): the
// unit vector from the Earth's centre through the sub-solar point (the sun is far enough
// that one direction lights the whole Earth: its day side is the half facing it).
Vec3 globe_sun_direction(double julian_day);

// The sun at `julian_day` (UTC) for a domain of longitudes [lon_lo, lon_hi] and
// latitudes [lat_lo, lat_hi] (degrees; lon_lo <= lon_hi, which may pass 180) centred at
// (lon0, lat0), by the rule above.
SunAtTime sun_for_domain(double julian_day, double lon_lo, double lon_hi, double lat_lo,
                         double lat_hi, double lon0, double lat0);

// "the true sun over the domain centre (51.00 N, 9.50 E), 35.2 degrees up" or "the sun
// over the domain's sunniest point (23.44 N, 0.12 W), 90.0 degrees up: the domain spans
// 358 degrees of longitude (more than 30)": the rule and its outcome, for the log.
std::string describe_sun(const SunAtTime& sun);

}  // namespace strielad::view
