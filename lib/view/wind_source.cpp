// SPDX-License-Identifier: Apache-2.0
#include "view/wind_source.h"

#include <cmath>
#include <sstream>

#include "core/error.h"
#include "view/level_heights.h"
#include "store/level_samples.h"
#include "view/default_scene.h"

namespace strielad::view {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

}  // namespace

WindNames parse_wind_names(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, ',');) parts.push_back(trim(part));
  if (parts.size() != 3 || parts[0].empty() || parts[1].empty() || parts[2].empty()) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "wind variables '{}': expected three names U,V,W (e.g. ua,va,wa)", text);
  }
  return WindNames{parts[0], parts[1], parts[2]};
}

WindUnits wind_units(const lod::WorldFrame& frame) {
  WindUnits units;
  // Degrees on longitude/latitude axes and on a rotated pole (a longitude/latitude grid
  // on a turned sphere: its grid-relative winds move it as winds move a geographic grid);
  // metres of map coordinates on Cartesian and projected axes (a projected grid's map
  // scale factor is not applied: a few percent off its standard parallels).
  if (frame.axis_length_km(0) == 0 || frame.axis_length_km(1) == 0) {
    units.horizontal = advect::Horizontal::kDegrees;
    units.scale[0] = units.scale[1] = 1.0;
  } else {
    units.horizontal = advect::Horizontal::kMetres;
    units.scale[0] = frame.axis_length_km(0) * 1000.0;
    units.scale[1] = frame.axis_length_km(1) * 1000.0;
  }
  units.vertical = frame.vertical() == lod::VerticalMap::kPressure ? advect::Vertical::kPascals
                                                                    : advect::Vertical::kMetres;
  units.scale[2] = frame.vertical_unit();
  return units;
}

std::uint32_t choose_wind_level(const OctreeLayout& layout, std::size_t max_samples) {
  for (std::size_t l = 0; l < layout.level_count(); ++l) {
    const auto& s = layout.level(l).samples;
    if (s[0] * s[1] * s[2] <= max_samples) return static_cast<std::uint32_t>(l);
  }
  return static_cast<std::uint32_t>(layout.level_count() - 1);
}

std::array<std::uint32_t, 3> wind_variables(const Store& store, const WindNames& names,
                                            std::uint32_t level) {
  const auto& manifest = store.manifest();
  if (level >= store.octree().level_count()) {
    throw make_error(ErrorCode::kInvalidArgument, "{}: wind level {}: the octree has {} levels",
                     store.path().string(), level, store.octree().level_count());
  }
  if (format::is_curvilinear(manifest)) {
    throw make_error(ErrorCode::kUnsupported,
                     "{}: advection on a curvilinear grid ('{}' / '{}') is not supported: its x "
                     "and y are grid indices whose spacing and direction change from cell to "
                     "cell, and the wind would first need the grid's local scale and rotation",
                     store.path().string(), manifest.geometry->horizontal.lon_variable,
                     manifest.geometry->horizontal.lat_variable);
  }
  if (!time_unit_seconds(manifest)) {
    throw make_error(ErrorCode::kUnsupported,
                     "{}: time axis '{}' has units '{}': advection needs '<seconds|minutes|"
                     "hours|days> since <date>'",
                     store.path().string(), manifest.time.name, manifest.time.units);
  }
  std::array<std::uint32_t, 3> variables{};
  const std::array<const std::string*, 3> wanted{&names.u, &names.v, &names.w};
  for (int c = 0; c < 3; ++c) {
    try {
      variables[c] = static_cast<std::uint32_t>(manifest.variable_index(*wanted[c]));
    } catch (const Error& e) {
      throw make_error(ErrorCode::kNotFound, "{}: wind component: {}", store.path().string(),
                       e.what());
    }
  }
  return variables;
}

WindStep load_wind_step(const Store& store, std::uint32_t step, const WindNames& names,
                        std::uint32_t level) {
  const auto& manifest = store.manifest();
  const auto& layout = store.octree();
  const std::array<std::uint32_t, 3> variables = wind_variables(store, names, level);
  if (step + 1 >= store.step_count()) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "{}: time step {}: no later step to advect towards (the store has {})",
                     store.path().string(), step, store.step_count());
  }
  const double seconds = (manifest.time.values[step + 1] - manifest.time.values[step]) *
                         *time_unit_seconds(manifest);
  if (!(seconds > 0) || !std::isfinite(seconds)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "{}: time steps {} and {} are not in increasing time ({} s apart)",
                     store.path().string(), step, step + 1, seconds);
  }

  const lod::WorldFrame frame(manifest, lod::WorldFrameOptions{.vertical_exaggeration = 1.0},
                              representative_level_heights_m(store),
                              store.horizontal_coordinates());
  const WindUnits units = wind_units(frame);
  advect::WindGrid grid;
  grid.horizontal = units.horizontal;
  grid.vertical = units.vertical;
  grid.periodic_x = manifest.x.periodic;  // clouds drift across a global grid's seam
  const LevelShape& shape = layout.level(level);
  const std::array<const std::vector<double>*, 3> axis_values{&manifest.x.values,
                                                              &manifest.y.values,
                                                              &manifest.z.values};
  for (int a = 0; a < 3; ++a) {
    for (std::size_t c = 0; c < shape.samples[a]; ++c) {
      grid.axes[a].push_back((*axis_values[a])[layout.fine_index(level, a, c)] *
                             units.scale[a]);
    }
  }
  std::uint64_t bytes = 0;
  // One component at one step on the level's grid, x fastest; NaN where missing.
  const auto read_level = [&](std::uint32_t at_step, std::uint32_t variable) {
    LevelSamples<float> level_samples = read_level_samples<float>(store, at_step, variable, level);
    bytes += level_samples.counts.sample_bytes;
    return std::move(level_samples.values);
  };
  std::array<advect::WindSlice, 2> slices;
  for (int t = 0; t < 2; ++t) {
    slices[t].u = read_level(step + t, variables[0]);
    slices[t].v = read_level(step + t, variables[1]);
    slices[t].w = read_level(step + t, variables[2]);
  }
  try {
    return WindStep{.field = advect::WindField(std::move(grid), 0.0, std::move(slices[0]),
                                               seconds, std::move(slices[1])),
                    .units = units,
                    .step = step,
                    .seconds = seconds,
                    .level = level,
                    .bytes_read = bytes};
  } catch (const Error& e) {
    throw make_error(e.code(), "{}: wind at level {}: {}", store.path().string(), level,
                     e.what());
  }
}

}  // namespace strielad::view
