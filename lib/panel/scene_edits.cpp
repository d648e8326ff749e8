// SPDX-License-Identifier: Apache-2.0
#include "panel/scene_edits.h"

#include <fmt/format.h>

#include <algorithm>

#include "core/error.h"
#include "view/default_scene.h"

namespace strielad::panel {
namespace {

void require_variables(const format::Manifest& manifest, const char* what) {
  if (manifest.variables.empty()) {
    throw make_error(ErrorCode::kInvalidArgument, "{}: the store has no variables", what);
  }
}

}  // namespace

AxisRange axis_extent(const Axis& axis) {
  if (axis.values.empty()) return {};
  const auto [lo, hi] = std::minmax(axis.values.front(), axis.values.back());
  return {lo, hi};
}

const Axis* axis_named(const format::Manifest& manifest, const std::string& name) {
  for (const Axis* axis : {&manifest.x, &manifest.y, &manifest.z}) {
    if (axis->name == name) return axis;
  }
  return nullptr;
}

AxisRange geographic_extent(const format::Manifest& manifest, GeographicCoordinate which) {
  switch (which) {
    case GeographicCoordinate::kLongitude:
      return manifest.x.kind == AxisKind::kLongitude ? axis_extent(manifest.x)
                                                           : AxisRange{-180, 180};
    case GeographicCoordinate::kLatitude:
      return manifest.y.kind == AxisKind::kLatitude ? axis_extent(manifest.y)
                                                          : AxisRange{-90, 90};
    case GeographicCoordinate::kHeight:
      return manifest.z.kind == AxisKind::kHeight ? axis_extent(manifest.z)
                                                        : AxisRange{0, 20000};
  }
  return {};
}

SubVolume new_subvolume(const Scene& scene, const format::Manifest& manifest) {
  require_variables(manifest, "new sub-volume");
  std::uint32_t id = 1;
  for (const auto& s : scene.subvolumes) id = std::max(id, s.id + 1);
  SubVolume s;
  s.id = id;
  s.name = fmt::format("sub-volume {}", id);
  const auto& var = manifest.variables.front().name;
  const auto range = view::variable_range(manifest, var);
  s.limits.push_back(Limit{.var = var,
                           .min = range ? 0.5 * (range->first + range->second) : 0.0,
                           .max = std::nullopt});
  return s;
}

Slice new_slice(const Scene& scene, const format::Manifest& manifest) {
  require_variables(manifest, "new slice");
  std::uint32_t id = 1;
  for (const auto& s : scene.slices) id = std::max(id, s.id + 1);
  const AxisRange z = axis_extent(manifest.z);
  Slice slice;
  slice.id = id;
  slice.name = fmt::format("slice {}", id);
  slice.axis = manifest.z.name;
  slice.value = 0.5 * (z.lo + z.hi);
  slice.var = manifest.variables.front().name;
  return slice;
}

std::string scene_problem(const Scene& scene, const format::Manifest& manifest) {
  try {
    (void)resolve_scene(scene, manifest, "scene");
    return {};
  } catch (const Error& e) {
    return e.what();
  }
}

}  // namespace strielad::panel
