// SPDX-License-Identifier: Apache-2.0
// What the viewer shows before the user describes a scene, and what it tells about the
// store's variables: the range of each variable's data (from the manifest summary) and
// the simulation time of each step in seconds.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "format/manifest.h"
#include "scene/scene.h"

namespace strielad::view {

// The paper's view of a store with cloud variables: "cloud water" clw >= 1e-5 kg/kg,
// "cloud ice" cli >= 1e-6 kg/kg, "rain" qr >= 1e-5 kg/kg (those present), with the
// attributes ta, ua, va, wa where present, at step `time`. A store without them: its
// first variable above the middle of its data range (when the manifest knows it).
// \error kInvalidArgument naming the store's variables when neither applies.
Scene default_scene(const format::Manifest& manifest, std::uint32_t time = 0);

// The exact [min, max] of a variable's valid data over all steps, from the manifest
// summary (formats/store.md); nothing for stores that do not record it.
std::optional<std::pair<double, double>> variable_range(const format::Manifest& manifest,
                                                        const std::string& variable);

// Seconds per unit of the time axis ("hours since ..." gives 3600); nothing when the
// units are not "<unit> since <date>" with a unit of seconds, minutes, hours or days.
std::optional<double> time_unit_seconds(const format::Manifest& manifest);

// Seconds from the first time step to step `step`, from the time axis units ("hours
// since ...", "seconds since ...", ...); the step index when the units are unknown.
double seconds_since_first_step(const format::Manifest& manifest, std::uint32_t step);

}  // namespace strielad::view
