// SPDX-License-Identifier: Apache-2.0
// The sun the viewer lights with (issue 8, "Sun"): the true direction towards the sun
// (geo/solar_position.h) at the simulation time, seen from the domain's centre, in the
// viewer's world frame (x east, y north, z up at the centre: the local east-north-up
// frame there). At night it points below the horizon, as it should: the user shaders
// decide what night looks like.
#pragma once

#include <cstdint>
#include <optional>

#include "format/manifest.h"
#include "geo/solar_position.h"
#include "lod/geometry.h"
#include "lod/world_frame.h"

namespace strielad::view {

struct SunAtTime {
  lod::Vec3 direction{};  // unit, world frame
  geo::SolarPosition position;
};

// The sun at time step `step` plus `seconds_after` seconds. Nothing when the frame is
// not geographic (no longitude/latitude to stand on) or the time axis has no real date
// (units not "<unit> since <date>", or a model calendar such as 360_day).
std::optional<SunAtTime> sun_at_step(const lod::WorldFrame& frame, const format::Manifest& manifest,
                                     std::uint32_t step, double seconds_after = 0);

}  // namespace strielad::view
