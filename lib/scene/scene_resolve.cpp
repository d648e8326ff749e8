// SPDX-License-Identifier: Apache-2.0
// Checks a scene against a store's manifest and turns names into indices
// (formats/scene.md, "Resolution against a store").
#include <algorithm>
#include <limits>
#include <string>

#include "core/error.h"
#include "format/geometry_field.h"
#include "format/manifest.h"
#include "grid/longitude_turns.h"
#include "scene/scene.h"
#include "scene/scene_errors.h"

namespace strielad {
namespace {

using scene_detail::fail;
using scene_detail::index_path;
using scene_detail::key_path;

constexpr double kInf = std::numeric_limits<double>::infinity();

class Names {
 public:
  Names(const format::Manifest& m, std::string_view what) : manifest_(m), what_(what) {}

  std::uint32_t variable(const std::string& name, const std::string& path) const {
    for (std::size_t i = 0; i < manifest_.variables.size(); ++i) {
      if (manifest_.variables[i].name == name) return static_cast<std::uint32_t>(i);
    }
    const std::string geometry = format::geometry_field_name(manifest_);
    if (!geometry.empty() && name == geometry) return *format::geometry_field_variable(manifest_);
    std::string list;
    for (const format::StoreVariable& v : manifest_.variables) {
      list += list.empty() ? v.name : fmt::format(", {}", v.name);
    }
    if (!geometry.empty()) list += fmt::format(", {} (the grid geometry)", geometry);
    fail(ErrorCode::kNotFound, what_, path, "variable '{}' is not in the store (it has: {})",
         scene_detail::shown(name), list);
  }

  std::size_t axis(const std::string& name, const std::string& path) const {
    const Axis* axes[3] = {&manifest_.x, &manifest_.y, &manifest_.z};
    for (std::size_t a = 0; a < 3; ++a) {
      if (axes[a]->name == name) return a;
    }
    fail(ErrorCode::kNotFound, what_, path,
         "axis '{}' is not an axis of the store (its axes: x {}, y {}, z {})",
         scene_detail::shown(name), manifest_.x.name, manifest_.y.name, manifest_.z.name);
  }

 private:
  const format::Manifest& manifest_;
  std::string_view what_;
};

// Smallest and largest coordinate of an axis (its values are strictly monotonic).
AxisRange extent(const Axis& axis) {
  if (axis.values.empty()) return AxisRange{kInf, -kInf};  // matches nothing
  return AxisRange{std::min(axis.values.front(), axis.values.back()),
                   std::max(axis.values.front(), axis.values.back())};
}

// A geographic height range: folded into the box on a height axis (exact planes), kept
// for per-sample evaluation on a terrain-following grid whose geometry field is a
// height; refused where the store has no heights (pressure or model levels).
void resolve_geographic_height(const AxisRange& height, const format::Manifest& m,
                               std::string_view what, const std::string& path, ResolvedSubVolume& r,
                               ResolvedScene& out) {
  const std::string field = format::geometry_field_name(m);
  if (field == "geometry_height") {
    r.geometry_height = height;
    out.needed_variables.push_back(*format::geometry_field_variable(m));
    return;
  }
  if (field.empty() && m.z.kind == AxisKind::kHeight) {
    const AxisRange e = extent(m.z);
    if (r.box[2].lo != -kInf || r.box[2].hi != kInf) {
      fail(ErrorCode::kInvalidInput, what, path,
           "the store's axis '{}' is the height already bounded in \"domain\"; give the range "
           "once",
           m.z.name);
    }
    if (height.hi < e.lo || height.lo > e.hi) {
      fail(ErrorCode::kInvalidInput, what, path,
           "[{}, {}] lies outside the store's heights [{}, {}] (axis '{}')", height.lo, height.hi,
           e.lo, e.hi, m.z.name);
    }
    r.box[2] = height;
    return;
  }
  fail(ErrorCode::kInvalidInput, what, path,
       "the store's levels have no height ({}): a height range needs a height axis or "
       "terrain-following levels placed by heights; bound {} in \"domain\" or with a limit "
       "instead",
       field.empty() ? fmt::format("axis '{}' is not a height", m.z.name)
                     : fmt::format("its grid geometry is the field '{}'", field),
       field.empty() ? fmt::format("'{}'", m.z.name) : fmt::format("'{}'", field));
}

// A geographic box on the store's grid: folded into the axis box on a longitude/latitude
// grid (exact planes); kept for per-sample evaluation on a mapped grid; refused on a grid
// without a place on the Earth.
void resolve_geographic(const GeographicBox& g, const format::Manifest& m, std::string_view what,
                        const std::string& path, ResolvedSubVolume& r) {
  const bool geographic_axes = m.x.kind == AxisKind::kLongitude && m.y.kind == AxisKind::kLatitude;
  // Placed by a grid mapping or by 2-D coordinates (curvilinear): evaluated per sample.
  const bool mapped = (m.grid_mapping && !m.grid_mapping->proj.empty()) || format::is_curvilinear(m);
  if (!geographic_axes && !mapped) {
    fail(ErrorCode::kInvalidInput, what, path,
         "the store's axes '{}' and '{}' have no place on the Earth (no grid_mapping), so a "
         "geographic box cannot be placed; use \"domain\" with the axes' own coordinates",
         m.x.name, m.y.name);
  }
  if (g.lat) {
    const AxisRange lat_extent = extent(geographic_axes ? m.y : Axis{});
    if (geographic_axes && (g.lat->hi < lat_extent.lo || g.lat->lo > lat_extent.hi)) {
      fail(ErrorCode::kInvalidInput, what, key_path(path, "lat"),
           "[{}, {}] lies outside the store's latitudes [{}, {}]", g.lat->lo, g.lat->hi,
           lat_extent.lo, lat_extent.hi);
    }
  }
  if (!geographic_axes) {
    GeographicBox kept = g;
    if (kept.lon && kept.lon->hi - kept.lon->lo >= kFullTurn) kept.lon.reset();
    if (kept.lon || kept.lat) r.geographic = kept;
    return;
  }
  auto fold = [&](int axis, const AxisRange& range, std::string_view key, const Axis& a) {
    if (r.box[axis].lo != -kInf || r.box[axis].hi != kInf) {
      fail(ErrorCode::kInvalidInput, what, key_path(path, key),
           "the store's axis '{}' is the {} already bounded in \"domain\"; give the range once",
           a.name, key == "lon" ? "longitude" : "latitude");
    }
    r.box[axis] = range;
  };
  if (g.lon) {
    const AxisRange e = extent(m.x);
    if (g.lon->hi - g.lon->lo < kFullTurn) {
      if (longitude_turns(g.lon->lo, g.lon->hi, e.lo, e.hi).empty()) {
        fail(ErrorCode::kInvalidInput, what, key_path(path, "lon"),
             "[{}, {}] selects no longitude of the store's {} axis [{}, {}] (in any convention)",
             g.lon->lo, g.lon->hi, m.x.name, e.lo, e.hi);
      }
      fold(0, *g.lon, "lon", m.x);
    }
  }
  if (g.lat) fold(1, *g.lat, "lat", m.y);
}

void check_time_step(std::size_t time, std::size_t steps, std::string_view what) {
  if (time < steps) return;
  if (steps == 0) {
    fail(ErrorCode::kNotFound, what, "time",
         "time step {} is out of range: the store has no time steps", time);
  }
  fail(ErrorCode::kNotFound, what, "time",
       "time step {} is out of range: the store has {} time steps (0..{})", time, steps, steps - 1);
}

// The axis ranges of a subvolume's "domain" (at `path`) into its box; a longitude range
// in any convention, a full turn or more being the whole axis.
void resolve_domain(const SubVolume& sv, const std::string& path, const format::Manifest& manifest,
                    const Names& names, std::string_view what, ResolvedSubVolume& r) {
  const Axis* axes[3] = {&manifest.x, &manifest.y, &manifest.z};
  for (const auto& [axis_name, range] : sv.domain) {
    const std::string p = key_path(path, axis_name);
    const std::size_t a = names.axis(axis_name, p);
    const AxisRange e = extent(*axes[a]);
    if (axes[a]->kind == AxisKind::kLongitude) {
      // Any convention: the range meets the axis at some whole turn (longitude_turns.h);
      // a full turn or more is the whole axis.
      if (range.hi - range.lo >= kFullTurn) {
        r.box[a] = AxisRange{-kInf, kInf};
        continue;
      }
      if (longitude_turns(range.lo, range.hi, e.lo, e.hi).empty()) {
        fail(ErrorCode::kInvalidInput, what, p,
             "[{}, {}] selects no longitude of the store's {} axis [{}, {}] (in any "
             "convention: shifted by any multiple of 360 it stays outside)",
             range.lo, range.hi, scene_detail::shown(axis_name), e.lo, e.hi);
      }
    } else if (range.hi < e.lo || range.lo > e.hi) {
      fail(ErrorCode::kInvalidInput, what, p, "[{}, {}] lies outside the store's {} axis [{}, {}]",
           range.lo, range.hi, scene_detail::shown(axis_name), e.lo, e.hi);
    }
    r.box[a] = range;
  }
}

ResolvedSubVolume resolve_subvolume(const SubVolume& sv, const std::string& path,
                                    const format::Manifest& manifest, const Names& names,
                                    std::string_view what, ResolvedScene& out) {
  ResolvedSubVolume r;
  r.id = sv.id;
  r.name = sv.name;
  for (std::size_t j = 0; j < sv.limits.size(); ++j) {
    const Limit& l = sv.limits[j];
    const std::string limit_path = index_path(key_path(path, "limits"), j);
    r.limits.push_back(ResolvedLimit{names.variable(l.var, key_path(limit_path, "var")),
                                     l.min.value_or(-kInf), l.max.value_or(kInf)});
    out.needed_variables.push_back(r.limits.back().variable);
  }
  r.box.fill(AxisRange{-kInf, kInf});
  resolve_domain(sv, key_path(path, "domain"), manifest, names, what, r);
  if (sv.geographic && (sv.geographic->lon || sv.geographic->lat)) {
    GeographicBox horizontal = *sv.geographic;
    horizontal.height.reset();
    resolve_geographic(horizontal, manifest, what, key_path(path, "geographic"), r);
  }
  if (sv.geographic && sv.geographic->height) {
    resolve_geographic_height(*sv.geographic->height, manifest, what,
                              key_path(key_path(path, "geographic"), "height"), r, out);
  }
  return r;
}

ResolvedSlice resolve_slice(const Slice& slice, const std::string& path,
                            const format::Manifest& manifest, const Names& names,
                            std::string_view what, ResolvedScene& out) {
  const Axis* axes[3] = {&manifest.x, &manifest.y, &manifest.z};
  ResolvedSlice r;
  r.id = slice.id;
  r.name = slice.name;
  r.value = slice.value;
  r.colormap = slice.colormap;
  r.range = slice.range;
  if (slice.is_level()) {
    r.level_variable = names.variable(slice.level_var, key_path(key_path(path, "level"), "var"));
    out.needed_variables.push_back(r.level_variable);
  } else {
    const std::size_t a = names.axis(slice.axis, key_path(path, "axis"));
    const AxisRange e = extent(*axes[a]);
    if (axes[a]->kind == AxisKind::kLongitude && (slice.value < e.lo || slice.value > e.hi)) {
      // A meridian in another convention: the same meridian of the axis, if it has it.
      const auto turns = longitude_turns(slice.value, slice.value, e.lo, e.hi);
      if (!turns.empty()) r.value = slice.value - kFullTurn * turns.front();
    }
    if (r.value < e.lo || r.value > e.hi) {
      fail(ErrorCode::kInvalidInput, what, key_path(path, "value"),
           "{} lies outside the store's {} axis [{}, {}]", slice.value,
           scene_detail::shown(slice.axis), e.lo, e.hi);
    }
    r.axis = static_cast<int>(a);
  }
  r.variable = names.variable(slice.var, key_path(path, "var"));
  out.needed_variables.push_back(r.variable);
  return r;
}

}  // namespace

ResolvedScene resolve_scene(const Scene& scene, const format::Manifest& manifest,
                            std::string_view what) {
  validate_scene(scene, what);
  const Names names(manifest, what);
  check_time_step(scene.time, manifest.time.size(), what);
  ResolvedScene out;
  out.time = scene.time;
  for (std::size_t i = 0; i < scene.subvolumes.size(); ++i) {
    out.subvolumes.push_back(resolve_subvolume(scene.subvolumes[i], index_path("subvolumes", i),
                                               manifest, names, what, out));
  }
  for (std::size_t k = 0; k < scene.attributes.size(); ++k) {
    out.attributes.push_back(names.variable(scene.attributes[k], index_path("attributes", k)));
    out.needed_variables.push_back(out.attributes.back());
  }
  for (std::size_t i = 0; i < scene.slices.size(); ++i) {
    out.slices.push_back(
        resolve_slice(scene.slices[i], index_path("slices", i), manifest, names, what, out));
  }
  std::sort(out.needed_variables.begin(), out.needed_variables.end());
  out.needed_variables.erase(std::unique(out.needed_variables.begin(), out.needed_variables.end()),
                             out.needed_variables.end());
  return out;
}

}  // namespace strielad
