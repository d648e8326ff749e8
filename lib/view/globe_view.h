// SPDX-License-Identifier: Apache-2.0
// Where the viewer's camera starts on the globe (lod/world_frame.h, FrameShape::kGlobe),
// and the orbit camera for any frame (view/orbit_camera.h).
#pragma once

#include <array>
#include <cstdint>

#include "format/manifest.h"
#include "lod/world_frame.h"
#include "view/orbit_camera.h"

namespace strielad::view {

// The point the home view looks down on: {longitude, latitude} (degrees). The domain's
// centre; a domain that spans at least half the Earth's longitudes, at a time step with a
// real date, is seen over its sub-solar point instead, so that home shows the day side
// (as the paper's figure of the whole planet with the sun at the simulation time).
std::array<double, 2> globe_home_point(const lod::WorldFrame& frame,
                                       const format::Manifest& manifest, std::uint32_t step);

// The orbit camera at its home view: about the domain on the plane, about the Earth's
// centre over globe_home_point on the globe.
OrbitCamera home_orbit_camera(const lod::WorldFrame& frame, const format::Manifest& manifest,
                              std::uint32_t step);

}  // namespace strielad::view
