// SPDX-License-Identifier: Apache-2.0
#include "ingest/horizontal_axes.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>

#include "core/error.h"
#include "geo/cf_grid_mapping.h"
#include "ingest/cf_axis_detection.h"

namespace strielad::ingest {
namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

enum class Horizontal {
  kGeographic,       // said so by units or standard_name
  kMaybeGeographic,  // only the name (or units "degrees") suggests it
  kRotated,          // grid_longitude / grid_latitude
  kProjected,        // projection_x/y_coordinate or a length
};

Horizontal classify(const Axis& a) {
  const std::string sn = lower(a.standard_name);
  if (sn == "grid_longitude" || sn == "grid_latitude") return Horizontal::kRotated;
  if (sn == "projection_x_coordinate" || sn == "projection_y_coordinate" ||
      sn == "projection_x_angular_coordinate" || sn == "projection_y_angular_coordinate") {
    return Horizontal::kProjected;
  }
  if (sn == "longitude" || sn == "latitude" || is_longitude_units(a.units) ||
      is_latitude_units(a.units)) {
    return Horizontal::kGeographic;
  }
  if (is_length_units(a.units)) return Horizontal::kProjected;
  std::string stem = lower(a.name);
  while (!stem.empty() && (std::isdigit(static_cast<unsigned char>(stem.back())) || stem.back() == '_')) {
    stem.pop_back();
  }
  if (stem == "rlon" || stem == "rlat") return Horizontal::kRotated;
  return Horizontal::kMaybeGeographic;
}

std::string_view describe(Horizontal h) {
  switch (h) {
    case Horizontal::kGeographic:
    case Horizontal::kMaybeGeographic: return "longitude/latitude";
    case Horizontal::kRotated: return "rotated-pole coordinates";
    case Horizontal::kProjected: return "projection coordinates";
  }
  return "";
}

// Unwraps a wrapped longitude axis and closes one that goes round the Earth; true when
// the first meridian was appended.
bool close_longitudes(Axis& x, HorizontalAxes& out, std::string_view what) {
  const std::vector<double> stored = x.values;
  if (unwrap_longitudes(x.values)) {
    std::size_t jump = 1;
    while (jump + 1 < stored.size() && std::abs(stored[jump] - stored[jump - 1]) <= 180) ++jump;
    out.notes.push_back(fmt::format(
        "{}: longitude axis '{}' wraps around ({} then {} at index {}); unwrapped to {} .. {}", what,
        x.name, stored[jump - 1], stored[jump], jump, x.values.front(), x.values.back()));
  }
  if (longitudes_repeat_the_first(x.values)) {
    x.periodic = true;
    out.notes.push_back(fmt::format(
        "{}: longitude axis '{}' goes round the Earth ({} .. {}, the first meridian repeated): "
        "periodic",
        what, x.name, x.values.front(), x.values.back()));
    return false;
  }
  if (longitudes_close_the_circle(x.values)) {
    const bool ascending = x.values.back() > x.values.front();
    x.values.push_back(x.values.front() + (ascending ? 360.0 : -360.0));
    x.periodic = true;
    out.notes.push_back(fmt::format(
        "{}: longitude axis '{}' goes round the Earth ({} .. {} every {:.6g} degrees): periodic, "
        "its first meridian repeated at {} so that the cell across {} is kept",
        what, x.name, stored.front(), stored.back(),
        std::fabs(x.values[1] - x.values[0]), x.values.back(), stored.back()));
    return true;
  }
  return false;
}

}  // namespace

HorizontalAxes place_horizontal_axes(Axis& x, Axis& y, std::optional<GridMapping> mapping,
                                     std::string_view what) {
  HorizontalAxes out;
  const Horizontal hx = classify(x), hy = classify(y);
  const bool x_geo = hx == Horizontal::kGeographic || hx == Horizontal::kMaybeGeographic;
  const bool y_geo = hy == Horizontal::kGeographic || hy == Horizontal::kMaybeGeographic;
  if (x_geo != y_geo || (!x_geo && hx != hy)) {
    throw make_error(ErrorCode::kUnsupported,
                     "{}: axis '{}' holds {} but axis '{}' holds {}; both horizontal axes must be "
                     "of one kind",
                     what, x.name, describe(hx), y.name, describe(hy));
  }
  if (mapping && lower(mapping->name) == "latitude_longitude") {
    if (!x_geo) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: grid mapping '{}' is latitude_longitude but axes '{}' and '{}' hold {}",
                       what, mapping->variable, x.name, y.name, describe(hx));
    }
    mapping->proj = geo::cf_grid_mapping_proj(*mapping, x, y, what);
  } else if (mapping) {
    if (hx == Horizontal::kGeographic || hy == Horizontal::kGeographic) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: axes '{}' and '{}' are longitude and latitude (units '{}', '{}'), but "
                       "the grid mapping '{}' ({}) is for projection coordinates",
                       what, x.name, y.name, x.units, y.units, mapping->variable, mapping->name);
    }
    x.kind = AxisKind::kProjectionX;
    y.kind = AxisKind::kProjectionY;
    mapping->proj = geo::cf_grid_mapping_proj(*mapping, x, y, what);
    out.notes.push_back(fmt::format("{}: axes '{}' and '{}' placed by grid mapping '{}' ({}): {}",
                                    what, x.name, y.name, mapping->variable, mapping->name,
                                    mapping->proj));
  } else if (hx == Horizontal::kRotated) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: axes '{}' and '{}' are rotated-pole coordinates but the variable has no "
                     "grid_mapping attribute, so where the pole is is unknown; add it (e.g. "
                     "ncatted -a grid_mapping,VAR,c,c,rotated_pole with a rotated_pole variable "
                     "holding grid_north_pole_latitude and grid_north_pole_longitude)",
                     what, x.name, y.name);
  } else if (hx == Horizontal::kProjected) {
    x.kind = AxisKind::kProjectionX;
    y.kind = AxisKind::kProjectionY;
    out.notes.push_back(fmt::format(
        "{}: axes '{}' and '{}' are projection coordinates ({}) without a grid_mapping: a "
        "Cartesian grid with no place on the Earth (no geographic frames, terrain, tracks or "
        "true sun)",
        what, x.name, y.name, x.units));
  }
  const std::size_t source_nx = x.values.size();
  if (x.kind == AxisKind::kLongitude) close_longitudes(x, out, what);
  out.mapping = std::move(mapping);
  out.source_nx = source_nx;
  return out;
}

}  // namespace strielad::ingest
