// SPDX-License-Identifier: Apache-2.0
// The scene rules that need no store (formats/scene.md, "Sizes" and "What a reader must
// reject"), applied to the Scene struct so that scenes built in code get them too.
#include <cmath>
#include <map>
#include <string>

#include "core/error.h"
#include "scene/scene.h"
#include "scene/scene_errors.h"

namespace strielad {
namespace {

using scene_detail::fail;
using scene_detail::index_path;
using scene_detail::key_path;

// Strict UTF-8 (RFC 3629): no overlong forms, no surrogates, nothing above U+10FFFF.
bool valid_utf8(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size()) {
    const auto c = static_cast<unsigned char>(s[i]);
    std::size_t extra = 0;
    unsigned lo = 0x80, hi = 0xBF;  // allowed range of the first continuation byte
    if (c < 0x80) {
      ++i;
      continue;
    } else if (c >= 0xC2 && c <= 0xDF) {
      extra = 1;
    } else if (c >= 0xE0 && c <= 0xEF) {
      extra = 2;
      if (c == 0xE0) lo = 0xA0;
      if (c == 0xED) hi = 0x9F;
    } else if (c >= 0xF0 && c <= 0xF4) {
      extra = 3;
      if (c == 0xF0) lo = 0x90;
      if (c == 0xF4) hi = 0x8F;
    } else {
      return false;
    }
    if (s.size() - i <= extra) return false;
    for (std::size_t k = 1; k <= extra; ++k) {
      const auto b = static_cast<unsigned char>(s[i + k]);
      if (k == 1 ? (b < lo || b > hi) : (b < 0x80 || b > 0xBF)) return false;
    }
    i += extra + 1;
  }
  return true;
}

void check_name(std::string_view what, const std::string& path, const std::string& name,
                std::string_view of) {
  if (name.empty()) fail(ErrorCode::kInvalidInput, what, path, "must name {}, got \"\"", of);
  if (!valid_utf8(name)) fail(ErrorCode::kInvalidInput, what, path, "is not valid UTF-8");
}

void check_finite(std::string_view what, const std::string& path, double value) {
  if (!std::isfinite(value)) {
    fail(ErrorCode::kInvalidInput, what, path, "must be a finite number, got {}", value);
  }
}

void check_limit(std::string_view what, const std::string& path, const Limit& limit) {
  check_name(what, key_path(path, "var"), limit.var, "a variable");
  if (!limit.min && !limit.max) {
    fail(ErrorCode::kInvalidInput, what, path, "a limit needs 'min', 'max' or both");
  }
  if (limit.min) check_finite(what, key_path(path, "min"), *limit.min);
  if (limit.max) check_finite(what, key_path(path, "max"), *limit.max);
  if (limit.min && limit.max && *limit.min > *limit.max) {
    fail(ErrorCode::kInvalidInput, what, path, "min {} is greater than max {}", *limit.min,
         *limit.max);
  }
}

void check_subvolume(std::string_view what, const std::string& path, const SubVolume& sv) {
  if (sv.id < 1 || sv.id > kMaxSubVolumeId) {
    fail(ErrorCode::kInvalidInput, what, key_path(path, "id"), "must be an integer in 1..{}, got {}",
         kMaxSubVolumeId, sv.id);
  }
  if (sv.name.size() > kMaxSubVolumeNameBytes) {
    fail(ErrorCode::kInvalidInput, what, key_path(path, "name"),
         "has {} bytes, more than the limit of {}", sv.name.size(), kMaxSubVolumeNameBytes);
  }
  if (!valid_utf8(sv.name)) {
    fail(ErrorCode::kInvalidInput, what, key_path(path, "name"), "is not valid UTF-8");
  }
  const std::string limits_path = key_path(path, "limits");
  if (sv.limits.size() > kMaxLimitsPerSubVolume) {
    fail(ErrorCode::kInvalidInput, what, limits_path, "has {} limits, more than the limit of {}",
         sv.limits.size(), kMaxLimitsPerSubVolume);
  }
  for (std::size_t j = 0; j < sv.limits.size(); ++j) {
    check_limit(what, index_path(limits_path, j), sv.limits[j]);
  }
  const std::string domain_path = key_path(path, "domain");
  for (const auto& [axis, range] : sv.domain) {
    const std::string p = key_path(domain_path, axis);
    check_name(what, p, axis, "an axis");
    check_finite(what, index_path(p, 0), range.lo);
    check_finite(what, index_path(p, 1), range.hi);
    if (range.lo > range.hi) {
      fail(ErrorCode::kInvalidInput, what, p,
           "lo {} is greater than hi {} (a range is [smaller, larger] whatever the axis's order)",
           range.lo, range.hi);
    }
  }
  if (sv.geographic) {
    const std::string p = key_path(path, "geographic");
    if (!sv.geographic->lon && !sv.geographic->lat && !sv.geographic->height) {
      fail(ErrorCode::kInvalidInput, what, p, "needs at least one of 'lon', 'lat' and 'height'");
    }
    for (const auto& [key, range] : {std::pair{"lon", sv.geographic->lon}, std::pair{"lat", sv.geographic->lat},
                                     std::pair{"height", sv.geographic->height}}) {
      if (!range) continue;
      const std::string rp = key_path(p, key);
      check_finite(what, index_path(rp, 0), range->lo);
      check_finite(what, index_path(rp, 1), range->hi);
      if (range->lo > range->hi) {
        fail(ErrorCode::kInvalidInput, what, rp, "lo {} is greater than hi {}", range->lo, range->hi);
      }
    }
    if (sv.geographic->lat && (sv.geographic->lat->lo < -90 || sv.geographic->lat->hi > 90)) {
      fail(ErrorCode::kInvalidInput, what, key_path(p, "lat"),
           "[{}, {}] is not within [-90, 90] degrees", sv.geographic->lat->lo,
           sv.geographic->lat->hi);
    }
  }
  if (sv.limits.empty() && sv.domain.empty() && !sv.geographic) {
    fail(ErrorCode::kInvalidInput, what, path,
         "a sub-volume needs at least one limit, a domain axis or a geographic box");
  }
}

void check_slice(std::string_view what, const std::string& path, const Slice& slice) {
  if (slice.id < 1 || slice.id > kMaxSliceId) {
    fail(ErrorCode::kInvalidInput, what, key_path(path, "id"), "must be an integer in 1..{}, got {}",
         kMaxSliceId, slice.id);
  }
  if (slice.name.size() > kMaxSubVolumeNameBytes) {
    fail(ErrorCode::kInvalidInput, what, key_path(path, "name"),
         "has {} bytes, more than the limit of {}", slice.name.size(), kMaxSubVolumeNameBytes);
  }
  if (!valid_utf8(slice.name)) {
    fail(ErrorCode::kInvalidInput, what, key_path(path, "name"), "is not valid UTF-8");
  }
  if (slice.axis.empty() == slice.level_var.empty()) {
    fail(ErrorCode::kInvalidInput, what, path,
         "a slice needs exactly one of 'axis' (a plane) and 'level' (an iso-level)");
  }
  if (slice.is_level()) {
    check_name(what, key_path(key_path(path, "level"), "var"), slice.level_var, "a variable");
    check_finite(what, key_path(key_path(path, "level"), "value"), slice.value);
  } else {
    check_name(what, key_path(path, "axis"), slice.axis, "an axis");
    check_finite(what, key_path(path, "value"), slice.value);
  }
  check_name(what, key_path(path, "var"), slice.var, "a variable");
  bool known = false;
  std::string names;
  for (std::string_view c : kSliceColormaps) {
    known = known || c == slice.colormap;
    names += names.empty() ? std::string(c) : fmt::format(", {}", c);
  }
  if (!known) {
    fail(ErrorCode::kInvalidInput, what, key_path(path, "colormap"),
         "'{}' is not a colour map (known: {})", scene_detail::shown(slice.colormap), names);
  }
  if (slice.range) {
    const std::string p = key_path(path, "range");
    check_finite(what, index_path(p, 0), slice.range->lo);
    check_finite(what, index_path(p, 1), slice.range->hi);
    if (!(slice.range->lo < slice.range->hi)) {
      fail(ErrorCode::kInvalidInput, what, p, "lo {} must be less than hi {}", slice.range->lo,
           slice.range->hi);
    }
  }
}

void check_path(std::string_view what, const std::string& path, const std::string& file) {
  check_name(what, path, file, "a file");
}

void check_geography(std::string_view what, const Scene& scene) {
  if (scene.slices.size() > kMaxSlices) {
    fail(ErrorCode::kInvalidInput, what, "slices", "has {} slices, more than the limit of {}",
         scene.slices.size(), kMaxSlices);
  }
  std::map<std::uint32_t, std::size_t> first_with_id;
  for (std::size_t i = 0; i < scene.slices.size(); ++i) {
    const std::string path = index_path("slices", i);
    check_slice(what, path, scene.slices[i]);
    if (const auto [it, fresh] = first_with_id.emplace(scene.slices[i].id, i); !fresh) {
      fail(ErrorCode::kInvalidInput, what, key_path(path, "id"),
           "id {} is already used by slices[{}]", scene.slices[i].id, it->second);
    }
  }
  if (scene.terrain) {
    check_path(what, "terrain.dem", scene.terrain->dem);
    if (!valid_utf8(scene.terrain->var)) {
      fail(ErrorCode::kInvalidInput, what, "terrain.var", "is not valid UTF-8");
    }
    if (!valid_utf8(scene.terrain->image)) {
      fail(ErrorCode::kInvalidInput, what, "terrain.image", "is not valid UTF-8");
    }
  }
  if (scene.sun && !scene.sun->from_time) {
    check_finite(what, "sun.elevation", scene.sun->elevation_deg);
    check_finite(what, "sun.azimuth", scene.sun->azimuth_deg);
    if (scene.sun->elevation_deg < -90 || scene.sun->elevation_deg > 90) {
      fail(ErrorCode::kInvalidInput, what, "sun.elevation", "must be in [-90, 90] degrees, got {}",
           scene.sun->elevation_deg);
    }
    if (scene.sun->azimuth_deg < 0 || scene.sun->azimuth_deg > 360) {
      fail(ErrorCode::kInvalidInput, what, "sun.azimuth", "must be in [0, 360] degrees, got {}",
           scene.sun->azimuth_deg);
    }
  }
  if (scene.trajectories) {
    check_path(what, "trajectories.file", scene.trajectories->file);
    check_finite(what, "trajectories.minutes", scene.trajectories->minutes);
    if (!(scene.trajectories->minutes > 0)) {
      fail(ErrorCode::kInvalidInput, what, "trajectories.minutes", "must be greater than 0, got {}",
           scene.trajectories->minutes);
    }
  }
}

}  // namespace

void validate_scene(const Scene& scene, std::string_view what) {
  if (scene.subvolumes.empty()) {
    fail(ErrorCode::kInvalidInput, what, "subvolumes", "a scene needs at least one sub-volume");
  }
  if (scene.subvolumes.size() > kMaxSubVolumes) {
    fail(ErrorCode::kInvalidInput, what, "subvolumes",
         "has {} sub-volumes, more than the limit of {}", scene.subvolumes.size(), kMaxSubVolumes);
  }
  std::map<std::uint32_t, std::size_t> first_with_id;
  for (std::size_t i = 0; i < scene.subvolumes.size(); ++i) {
    const SubVolume& sv = scene.subvolumes[i];
    const std::string path = index_path("subvolumes", i);
    check_subvolume(what, path, sv);
    if (const auto [it, fresh] = first_with_id.emplace(sv.id, i); !fresh) {
      fail(ErrorCode::kInvalidInput, what, key_path(path, "id"),
           "id {} is already used by subvolumes[{}]", sv.id, it->second);
    }
  }
  if (scene.attributes.size() > kMaxSceneAttributes) {
    fail(ErrorCode::kInvalidInput, what, "attributes", "has {} names, more than the limit of {}",
         scene.attributes.size(), kMaxSceneAttributes);
  }
  std::map<std::string_view, std::size_t> first_with_name;
  for (std::size_t k = 0; k < scene.attributes.size(); ++k) {
    const std::string path = index_path("attributes", k);
    check_name(what, path, scene.attributes[k], "a variable");
    if (const auto [it, fresh] = first_with_name.emplace(scene.attributes[k], k); !fresh) {
      fail(ErrorCode::kInvalidInput, what, path, "'{}' is already listed as attributes[{}]",
           scene_detail::shown(scene.attributes[k]), it->second);
    }
  }
  check_geography(what, scene);
}

}  // namespace strielad
