// SPDX-License-Identifier: Apache-2.0
#include "look_choice.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.h"
#include "render/surface_scalar_look.h"
#include "scene/scene.h"
#include "view/default_scene.h"
#include "view/node_geometry.h"

namespace strielad::view_cmd {
namespace {

std::vector<std::string> comma_list(const std::string& text) {
  std::vector<std::string> items;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    item.erase(0, item.find_first_not_of(' '));
    item.erase(item.find_last_not_of(' ') + 1);
    items.push_back(item);
  }
  return items;
}

// --color-range LO,HI.
std::pair<double, double> parse_range(const std::string& text) {
  const auto parts = comma_list(text);
  try {
    if (parts.size() == 2) {
      std::size_t used_lo = 0, used_hi = 0;
      const double lo = std::stod(parts[0], &used_lo), hi = std::stod(parts[1], &used_hi);
      if (used_lo == parts[0].size() && used_hi == parts[1].size() && lo < hi &&
          std::isfinite(lo) && std::isfinite(hi)) {
        return {lo, hi};
      }
    }
  } catch (const std::exception&) {
  }
  throw make_error(ErrorCode::kInvalidArgument, "--color-range {}: give LO,HI with LO < HI",
                   text);
}

// The store's data range of the value: the variable's own, or for a vector from 0 to
// the magnitude of its largest components.
std::pair<double, double> store_range(const format::Manifest& manifest,
                                      const std::vector<std::string>& names) {
  double largest = 0;
  for (const auto& name : names) {
    const auto r = view::variable_range(manifest, name);
    if (!r) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "--color-by {}: the store records no data range of '{}'; give "
                       "--color-range LO,HI",
                       fmt::join(names, ","), name);
    }
    if (names.size() == 1) {
      return r->first < r->second ? *r : std::pair{r->first, r->first + 1};
    }
    const double m = std::max(std::abs(r->first), std::abs(r->second));
    largest += m * m;
  }
  return {0.0, std::sqrt(largest) > 0 ? std::sqrt(largest) : 1.0};
}

std::string legend_title(const format::Manifest& manifest, const std::vector<std::string>& names) {
  const auto& first = manifest.variables[manifest.variable_index(names[0])];
  const std::string units = first.units.empty() ? "" : fmt::format(" ({})", first.units);
  if (names.size() == 1) return names[0] + units;
  return fmt::format("magnitude of {}{}", fmt::join(names, ", "), units);
}

}  // namespace

std::optional<render::ColourBarLegend> apply_look(const ViewerArgs& args, ViewerSession& session) {
  if (args.look == "clouds") {
    if (!args.color_by.empty() || !args.color_range.empty()) {
      spdlog::warn("--color-by and --color-range are for --look scalar; ignored");
    }
    return std::nullopt;
  }
  if (args.look != "scalar") {
    throw make_error(ErrorCode::kInvalidArgument, "--look {}: give clouds or scalar", args.look);
  }
  if (!args.shader_file.empty()) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "--look scalar and --shader {}: give one (the look is a built-in shader)",
                     args.shader_file);
  }
  const auto names = comma_list(args.color_by);
  if (args.color_by.empty() || names.empty() || names.size() > 3) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "--look scalar needs --color-by VAR (or U,V[,W] for a vector's "
                     "magnitude), got '{}'",
                     args.color_by);
  }
  const auto& maps = kSliceColormaps;
  if (std::find(maps.begin(), maps.end(), args.colormap) == maps.end()) {
    throw make_error(ErrorCode::kInvalidArgument, "--colormap {}: give one of {}", args.colormap,
                     fmt::join(maps, ", "));
  }
  const auto& manifest = session.link->manifest();
  render::SurfaceScalarLook look;
  look.colormap = args.colormap;
  auto& attributes = session.scene.attributes;
  for (const auto& name : names) {
    const auto& vars = manifest.variables;
    if (std::none_of(vars.begin(), vars.end(), [&](const auto& v) { return v.name == name; })) {
      std::vector<std::string> known;
      for (const auto& v : vars) known.push_back(v.name);
      throw make_error(ErrorCode::kNotFound, "--color-by {}: variable '{}' is not in the store "
                       "(it has: {})", args.color_by, name, fmt::join(known, ", "));
    }
    auto at = std::find(attributes.begin(), attributes.end(), name);
    if (at == attributes.end()) {
      if (attributes.size() >= view::kViewAttributeSlots) {
        throw make_error(ErrorCode::kInvalidArgument,
                         "--color-by {}: the scene already has {} attributes ({}), the most "
                         "the viewer carries; drop one from the scene",
                         name, attributes.size(), fmt::join(attributes, ", "));
      }
      attributes.push_back(name);
      at = attributes.end() - 1;
    }
    look.components.push_back(static_cast<int>(at - attributes.begin()));
  }
  std::tie(look.lo, look.hi) =
      args.color_range.empty() ? store_range(manifest, names) : parse_range(args.color_range);
  session.shader_source = render::surface_scalar_shader(look);
  session.shader_name = "built-in surface_scalar.glsl";
  return render::ColourBarLegend{legend_title(manifest, names), args.colormap, look.lo, look.hi};
}

}  // namespace strielad::view_cmd
