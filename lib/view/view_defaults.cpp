// SPDX-License-Identifier: Apache-2.0
// What the viewer chooses when the user does not: the default scene
// (view/default_scene.h), the vertical exaggeration (view/default_exaggeration.h), and
// the log lines that report both (view/view_choices.h).
#include "view/default_scene.h"
#include "view/default_exaggeration.h"
#include "view/view_choices.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "core/error.h"
#include "geo/cf_time.h"

namespace strielad::view {
namespace {

bool has_variable(const format::Manifest& m, const std::string& name) {
  return std::any_of(m.variables.begin(), m.variables.end(),
                     [&](const auto& v) { return v.name == name; });
}

}  // namespace

std::optional<std::pair<double, double>> variable_range(const format::Manifest& manifest,
                                                        const std::string& variable) {
  const auto& summary = manifest.summary;
  if (!summary.is_object() || !summary.contains("variables")) return std::nullopt;
  const auto& variables = summary["variables"];
  if (!variables.is_object() || !variables.contains(variable)) return std::nullopt;
  const auto& v = variables[variable];
  if (!v.is_object() || !v.contains("min") || !v.contains("max") || !v["min"].is_number() ||
      !v["max"].is_number()) {
    return std::nullopt;
  }
  return std::make_pair(v["min"].get<double>(), v["max"].get<double>());
}

Scene default_scene(const format::Manifest& manifest, std::uint32_t time) {
  Scene scene;
  scene.time = time;
  struct Cloud {
    const char* var;
    const char* name;
    double min;
  };
  const Cloud clouds[] = {{"clw", "cloud water", 1e-5}, {"cli", "cloud ice", 1e-6},
                          {"qr", "rain", 1e-5}};
  std::uint32_t id = 1;
  for (const auto& c : clouds) {
    if (!has_variable(manifest, c.var)) continue;
    SubVolume s;
    s.id = id++;
    s.name = c.name;
    s.limits.push_back(Limit{.var = c.var, .min = c.min, .max = std::nullopt});
    scene.subvolumes.push_back(std::move(s));
  }
  if (scene.subvolumes.empty() && !manifest.variables.empty()) {
    const auto& first = manifest.variables.front().name;
    if (const auto range = variable_range(manifest, first); range && range->first < range->second) {
      SubVolume s;
      s.id = 1;
      s.name = first;
      s.limits.push_back(Limit{.var = first, .min = 0.5 * (range->first + range->second),
                               .max = std::nullopt});
      scene.subvolumes.push_back(std::move(s));
    }
  }
  if (scene.subvolumes.empty()) {
    std::string names;
    for (const auto& v : manifest.variables) names += (names.empty() ? "" : ", ") + v.name;
    throw make_error(ErrorCode::kInvalidArgument,
                     "no default scene for a store with variables {}: give one with --scene",
                     names);
  }
  for (const char* a : {"ta", "ua", "va", "wa"}) {
    if (has_variable(manifest, a)) scene.attributes.emplace_back(a);
  }
  return scene;
}

std::optional<double> time_unit_seconds(const format::Manifest& manifest) {
  const auto& units = manifest.time.units;
  const auto since = units.find(" since ");
  if (since == std::string::npos) return std::nullopt;
  const auto first = units.find_first_not_of(' ');
  return geo::cf_unit_seconds(std::string_view(units).substr(first, since - first));
}

double seconds_since_first_step(const format::Manifest& manifest, std::uint32_t step) {
  const auto& t = manifest.time;
  if (step >= t.values.size()) return 0;
  const auto factor = time_unit_seconds(manifest);
  if (!factor) return step;
  return (t.values[step] - t.values.front()) * *factor;
}

namespace {

// E before rounding; NaN when the extent has no usable size.
double raw_exaggeration(const DomainExtent& e) {
  const double horizontal = std::sqrt(e.width_km * e.length_km);
  if (!std::isfinite(horizontal) || !std::isfinite(e.depth_km) || !(horizontal > 0) ||
      !(e.depth_km > 0)) {
    return NAN;
  }
  return kExaggeratedDepthShare * horizontal / e.depth_km;
}

// The nearest (by ratio) of 1, 2, 5 times a power of ten.
double round_1_2_5(double value) {
  const double decade = std::pow(10.0, std::floor(std::log10(value)));
  double best = decade;
  for (const double m : std::array{1.0, 2.0, 5.0, 10.0}) {
    if (std::fabs(std::log(value / (m * decade))) < std::fabs(std::log(value / best))) {
      best = m * decade;
    }
  }
  return best;
}

}  // namespace

DomainExtent domain_extent(const lod::WorldFrame& frame) {
  if (frame.globe()) {
    // The size on the ground, not the ECEF box: the tangent plane's extent.
    const auto b = frame.geographic_bounds();
    const double cos_lat0 = std::cos(frame.lat0() * std::numbers::pi / 180.0);
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t k = 0; k < frame.dims().z; ++k) {
      lo = std::min(lo, frame.sample_world_z(k));
      hi = std::max(hi, frame.sample_world_z(k));
    }
    return {(b.lon_hi - b.lon_lo) * lod::kKmPerDegree * cos_lat0,
            (b.lat_hi - b.lat_lo) * lod::kKmPerDegree, (hi - lo) / frame.vertical_exaggeration()};
  }
  const auto& d = frame.domain();
  return {d.hi[0] - d.lo[0], d.hi[1] - d.lo[1],
          (d.hi[2] - d.lo[2]) / frame.vertical_exaggeration()};
}

double default_vertical_exaggeration(const DomainExtent& extent) {
  const double raw = raw_exaggeration(extent);
  if (std::isnan(raw)) return lod::kDefaultVerticalExaggeration;
  return std::clamp(round_1_2_5(raw), kMinDefaultExaggeration, kMaxDefaultExaggeration);
}

std::string describe_default_exaggeration(const DomainExtent& extent) {
  const double raw = raw_exaggeration(extent);
  const double chosen = default_vertical_exaggeration(extent);
  if (std::isnan(raw)) {
    return fmt::format("{:g} for a {:.0f} x {:.0f} km domain {:.3g} km deep (no horizontal "
                       "size or no depth: the fixed default)",
                       chosen, extent.width_km, extent.length_km, extent.depth_km);
  }
  return fmt::format("{:g} for a {:.0f} x {:.0f} km domain {:.3g} km deep ({} x horizontal "
                     "size / depth = {:.3g}, rounded to 1-2-5{})",
                     chosen, extent.width_km, extent.length_km, extent.depth_km,
                     kExaggeratedDepthShare, raw,
                     round_1_2_5(raw) != chosen
                         ? fmt::format(", within {:g}..{:g}", kMinDefaultExaggeration,
                                       kMaxDefaultExaggeration)
                         : std::string());
}

std::vector<std::string> view_choice_lines(const ViewChoices& choices) {
  std::vector<std::string> lines;
  if (choices.default_scene) {
    lines.push_back("default scene (no --scene): " + scene_to_json(*choices.default_scene));
  }
  lines.push_back("vertical exaggeration " + choices.exaggeration);
  lines.push_back("sun: " + choices.sun);
  return lines;
}

void log_view_choices(const ViewChoices& choices) {
  for (const auto& line : view_choice_lines(choices)) spdlog::info("{}", line);
}

}  // namespace strielad::view
