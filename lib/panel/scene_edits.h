// SPDX-License-Identifier: Apache-2.0
// The panel's scene edits without the panel: the defaults of a new sub-volume or slice,
// the ranges its sliders are bounded by (the store's axes; the Earth's for geographic
// boxes), and the check an edited scene passes before the viewer is sent it.
#pragma once

#include <string>

#include "format/manifest.h"
#include "scene/scene.h"

namespace strielad::panel {

// The axis's [min, max] whatever its storage order.
AxisRange axis_extent(const Axis& axis);

// The store's axis called `name` (x, y or z), or null.
const Axis* axis_named(const format::Manifest& manifest, const std::string& name);

enum class GeographicCoordinate { kLongitude, kLatitude, kHeight };

// What a geographic box's sliders span: the x (y, z) axis's extent where it is a
// longitude (latitude, height) axis; otherwise the whole Earth (-180..180, -90..90) and
// heights of 0..20 km.
AxisRange geographic_extent(const format::Manifest& manifest, GeographicCoordinate which);

// A new sub-volume: the next free id, its first variable above the middle of its data
// range. \error kInvalidArgument when the store has no variables.
SubVolume new_subvolume(const Scene& scene, const format::Manifest& manifest);

// A new slice: the next free id, the plane through the middle of the z axis, coloured by
// the first variable with the default colour map and the viewer's colour range.
// \error kInvalidArgument when the store has no variables.
Slice new_slice(const Scene& scene, const format::Manifest& manifest);

// Why the store would refuse the scene (resolve_scene's message), or "" when it is valid.
std::string scene_problem(const Scene& scene, const format::Manifest& manifest);

}  // namespace strielad::panel
