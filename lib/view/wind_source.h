// SPDX-License-Identifier: Apache-2.0
// The wind a viewer advects its meshes with: the store's wind components at two
// consecutive time steps, read from one octree level (store/level_samples.h) and
// assembled into an advect::WindField in the units lib/advect integrates in.
//
// Units: lib/advect wants degrees on geographic x/y, metres on metric x/y and on a
// height axis, pascals on a pressure axis. WindUnits converts between those and the
// store's axis units (e.g. km, hPa) with one scale per axis.
//
// The level: wind for display does not need full resolution. choose_wind_level picks
// the finest level with at most `max_samples` samples (default 4 M: 96 MB of float wind
// for the two steps; level 3 of the paper's 1429 x 1556 x 150 grid, 180 x 196 x 20).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "advect/wind_field.h"
#include "lod/world_frame.h"
#include "store/store.h"

namespace strielad::view {

inline constexpr std::size_t kDefaultWindSamples = std::size_t{4} << 20;

struct WindNames {
  std::string u = "ua", v = "va", w = "wa";
};

// \error kInvalidArgument naming the text when it is not three comma-separated names.
WindNames parse_wind_names(const std::string& text);

// Axis units of a store <-> the units of advect::WindField.
struct WindUnits {
  std::array<double, 3> scale{1, 1, 1};  // wind-field unit per axis unit
  advect::Horizontal horizontal = advect::Horizontal::kDegrees;
  advect::Vertical vertical = advect::Vertical::kMetres;

  Vec3 to_wind(const Vec3& axis) const {
    return {axis[0] * scale[0], axis[1] * scale[1], axis[2] * scale[2]};
  }
  Vec3 to_axis(const Vec3& wind) const {
    return {wind[0] / scale[0], wind[1] / scale[1], wind[2] / scale[2]};
  }
};

// \error as lod::WorldFrame for axes without a world position.
WindUnits wind_units(const lod::WorldFrame& frame);

// The finest level with at most max_samples samples (the root's level if none).
std::uint32_t choose_wind_level(const OctreeLayout& layout,
                                std::size_t max_samples = kDefaultWindSamples);

// The store's indices of the wind components, once it is clear the store can be
// advected at `level`. \error kNotFound naming the store and component when a wind
// variable is missing; kUnsupported for time units advection cannot convert to seconds;
// kInvalidArgument when `level` is not in the octree.
std::array<std::uint32_t, 3> wind_variables(const Store& store, const WindNames& names,
                                            std::uint32_t level);

struct WindStep {
  advect::WindField field;
  WindUnits units;
  std::uint32_t step = 0;      // the field runs from this step (t = 0 s) ...
  double seconds = 0;          // ... to the next one (t = seconds)
  std::uint32_t level = 0;
  std::uint64_t bytes_read = 0;  // bytes of the bricks' samples read (decoded)
};

// The wind between `step` and `step + 1` at `level`, every brick of the level read
// (in parallel). Missing samples (fill) stay NaN: trajectories stop there, flagged.
// \error as wind_variables; kInvalidArgument when `step` is the last step (no next one
// to advect towards) or the two steps are not in increasing time; the store's read
// errors (kCorrupt naming file, variable and node).
WindStep load_wind_step(const Store& store, std::uint32_t step, const WindNames& names,
                        std::uint32_t level);

}  // namespace strielad::view
