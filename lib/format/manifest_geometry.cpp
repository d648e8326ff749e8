// SPDX-License-Identifier: Apache-2.0
#include "format/manifest_geometry.h"

#include <cmath>
#include <initializer_list>

#include "core/error.h"
#include "format/json_fields.h"
#include "format/manifest.h"

namespace strielad::format {
namespace {

using nlohmann::json;
using json_fields::get;

constexpr std::string_view kCurvilinear = "curvilinear", kAxes = "axes";

using json_fields::hex64;

// The rules a geometry must follow, for writers (kInvalidArgument) and readers (kCorrupt).
void check_geometry(const GridGeometry& g, std::size_t z_size, std::string_view what,
                    ErrorCode code) {
  const HorizontalGeometry& h = g.horizontal;
  if (h.kind == HorizontalGeometry::Kind::kCurvilinear) {
    if (h.lon_variable.empty() || h.lat_variable.empty()) {
      throw make_error(code, "{}: geometry.horizontal: a curvilinear grid needs '{}' names "
                             "(lon_variable '{}', lat_variable '{}')",
                       what, h.lon_variable.empty() ? "lon_variable" : "lat_variable",
                       h.lon_variable, h.lat_variable);
    }
    if (h.lon_variable == h.lat_variable) {
      throw make_error(code, "{}: geometry.horizontal: lon_variable and lat_variable are both '{}'",
                       what, h.lon_variable);
    }
  }
  const VerticalGeometry& v = g.vertical;
  if (v.kind != VerticalGeometry::Kind::kAxis) {
    const std::string_view kind = vertical_kind_name(v.kind);
    if (v.units != vertical_quantity_units(v.quantity)) {
      throw make_error(code, "{}: geometry.vertical ({}): units '{}' must be '{}' for a {}", what,
                       kind, v.units, vertical_quantity_units(v.quantity),
                       vertical_quantity_name(v.quantity));
    }
    if (v.formula.empty()) {
      throw make_error(code, "{}: geometry.vertical ({}): empty 'formula'", what, kind);
    }
  }
  if (v.kind == VerticalGeometry::Kind::kLevels) {
    if (v.levels.size() != z_size) {
      throw make_error(code, "{}: geometry.vertical.levels has {} values for a z axis of {}", what,
                       v.levels.size(), z_size);
    }
    for (std::size_t k = 0; k < v.levels.size(); ++k) {
      if (!std::isfinite(v.levels[k])) {
        throw make_error(code, "{}: geometry.vertical.levels[{}] is not finite", what, k);
      }
    }
    const bool ascending = v.levels.size() > 1 && v.levels[1] > v.levels[0];
    for (std::size_t k = 1; k < v.levels.size(); ++k) {
      if (ascending ? !(v.levels[k] > v.levels[k - 1]) : !(v.levels[k] < v.levels[k - 1])) {
        throw make_error(code,
                         "{}: geometry.vertical.levels are not strictly monotonic at index {} "
                         "({} after {})",
                         what, k, v.levels[k], v.levels[k - 1]);
      }
    }
  }
  if (v.kind == VerticalGeometry::Kind::kField) {
    const bool from_variable = v.formula == kGeometryFormulaVariable;
    if (from_variable && v.sources.empty()) {
      throw make_error(code, "{}: geometry.vertical (field): formula 'variable' with no 'sources'",
                       what);
    }
    if (!from_variable && v.terms.empty()) {
      throw make_error(code, "{}: geometry.vertical (field): formula '{}' with no 'terms'", what,
                       v.formula);
    }
    for (const auto& [term, variable] : v.terms) {
      if (term.empty() || variable.empty()) {
        throw make_error(code, "{}: geometry.vertical.terms: empty name in '{}': '{}'", what, term,
                         variable);
      }
    }
    try {
      validate_codec(v.codec);
    } catch (const Error& e) {
      throw make_error(code, "{}: geometry.vertical.codec: {}", what, e.what());
    }
    for (const std::string& source : v.sources) {
      if (source.empty()) {
        throw make_error(code, "{}: geometry.vertical.sources: empty variable name", what);
      }
    }
  }
  if (g.surface) {
    if (g.surface->variable.empty()) {
      throw make_error(code, "{}: geometry.surface: empty 'variable'", what);
    }
    if (g.surface->units != "m") {
      throw make_error(code, "{}: geometry.surface: units '{}' must be 'm'", what,
                       g.surface->units);
    }
  }
  if (g.orientation != 1 && g.orientation != -1) {
    throw make_error(code, "{}: geometry.orientation {} is not 1 or -1", what, g.orientation);
  }
  if (h.kind == HorizontalGeometry::Kind::kAxes && v.kind == VerticalGeometry::Kind::kAxis &&
      !g.surface) {
    throw make_error(code,
                     "{}: geometry places nothing (horizontal 'axes', vertical 'axis', no "
                     "surface): such a store has no geometry",
                     what);
  }
}

const json& object(const json& j, std::string_view key, std::string_view where) {
  const auto it = j.find(std::string(key));
  if (it == j.end()) throw make_error(ErrorCode::kCorrupt, "{}: missing key '{}'", where, key);
  if (!it->is_object()) {
    throw make_error(ErrorCode::kCorrupt, "{}: key '{}' is not an object", where, key);
  }
  return *it;
}

// Every key of `j` must be one of `allowed`.
void only_keys(const json& j, std::initializer_list<std::string_view> allowed,
               std::string_view where) {
  for (const auto& [key, value] : j.items()) {
    bool known = false;
    for (std::string_view a : allowed) known = known || key == a;
    if (!known) throw make_error(ErrorCode::kCorrupt, "{}: unknown key '{}'", where, key);
  }
}

HorizontalGeometry horizontal_from_json(const json& j, std::string_view what) {
  const std::string where = fmt::format("{}: geometry.horizontal", what);
  HorizontalGeometry h;
  const auto kind = get<std::string>(j, "kind", where);
  if (kind == kAxes) {
    only_keys(j, {"kind"}, where);
  } else if (kind == kCurvilinear) {
    only_keys(j, {"kind", "lon_variable", "lat_variable", "coordinates_checksum"}, where);
    h.kind = HorizontalGeometry::Kind::kCurvilinear;
    h.lon_variable = get<std::string>(j, "lon_variable", where);
    h.lat_variable = get<std::string>(j, "lat_variable", where);
    h.coordinates_checksum = json_fields::parse_hex64(
        get<std::string>(j, "coordinates_checksum", where), "coordinates_checksum", where);
  } else {
    throw make_error(ErrorCode::kCorrupt, "{}: unknown kind '{}' (axes, curvilinear)", where, kind);
  }
  return h;
}

VerticalGeometry::Quantity quantity_from_name(const std::string& name, std::string_view where) {
  if (name == "height") return VerticalGeometry::Quantity::kHeight;
  if (name == "pressure") return VerticalGeometry::Quantity::kPressure;
  throw make_error(ErrorCode::kCorrupt, "{}: unknown quantity '{}' (height, pressure)", where, name);
}

VerticalGeometry vertical_from_json(const json& j, std::string_view what) {
  const std::string where = fmt::format("{}: geometry.vertical", what);
  VerticalGeometry v;
  const auto kind = get<std::string>(j, "kind", where);
  if (kind == "axis") {
    only_keys(j, {"kind"}, where);
    return v;
  }
  if (kind == "levels") {
    only_keys(j, {"kind", "quantity", "units", "formula", "levels"}, where);
    v.kind = VerticalGeometry::Kind::kLevels;
    v.levels = get<std::vector<double>>(j, "levels", where);
  } else if (kind == "field") {
    only_keys(j, {"kind", "quantity", "units", "formula", "terms", "sources", "varies_in_time",
                  "dtype", "codec"},
              where);
    v.kind = VerticalGeometry::Kind::kField;
    v.terms = get<std::map<std::string, std::string>>(j, "terms", where);
    v.sources = get<std::vector<std::string>>(j, "sources", where);
    v.varies_in_time = get<bool>(j, "varies_in_time", where);
    try {
      v.dtype = dtype_from_name(get<std::string>(j, "dtype", where));
    } catch (const Error& e) {
      throw make_error(ErrorCode::kCorrupt, "{}: key 'dtype': {}", where, e.what());
    }
    v.codec = codec_from_json(get<json>(j, "codec", where), kManifestVersionGeometry,
                              fmt::format("{}.codec", where));
  } else {
    throw make_error(ErrorCode::kCorrupt, "{}: unknown kind '{}' (axis, levels, field)", where,
                     kind);
  }
  v.quantity = quantity_from_name(get<std::string>(j, "quantity", where), where);
  v.units = get<std::string>(j, "units", where);
  v.formula = get<std::string>(j, "formula", where);
  return v;
}

}  // namespace

std::string_view vertical_kind_name(VerticalGeometry::Kind kind) noexcept {
  switch (kind) {
    case VerticalGeometry::Kind::kAxis: return "axis";
    case VerticalGeometry::Kind::kLevels: return "levels";
    case VerticalGeometry::Kind::kField: return "field";
  }
  return "?";
}

std::string_view vertical_quantity_name(VerticalGeometry::Quantity quantity) noexcept {
  return quantity == VerticalGeometry::Quantity::kHeight ? "height" : "pressure";
}

std::string_view vertical_quantity_units(VerticalGeometry::Quantity quantity) noexcept {
  return quantity == VerticalGeometry::Quantity::kHeight ? "m" : "Pa";
}

json geometry_json(const GridGeometry& g, std::size_t z_size) {
  check_geometry(g, z_size, "manifest", ErrorCode::kInvalidArgument);
  json horizontal{{"kind", kAxes}};
  if (g.horizontal.kind == HorizontalGeometry::Kind::kCurvilinear) {
    horizontal = json{{"kind", kCurvilinear},
                      {"lon_variable", g.horizontal.lon_variable},
                      {"lat_variable", g.horizontal.lat_variable},
                      {"coordinates_checksum", hex64(g.horizontal.coordinates_checksum)}};
  }
  const VerticalGeometry& v = g.vertical;
  json vertical{{"kind", vertical_kind_name(v.kind)}};
  if (v.kind != VerticalGeometry::Kind::kAxis) {
    vertical["quantity"] = vertical_quantity_name(v.quantity);
    vertical["units"] = v.units;
    vertical["formula"] = v.formula;
  }
  if (v.kind == VerticalGeometry::Kind::kLevels) vertical["levels"] = v.levels;
  if (v.kind == VerticalGeometry::Kind::kField) {
    vertical["terms"] = v.terms;
    vertical["sources"] = v.sources;
    vertical["varies_in_time"] = v.varies_in_time;
    vertical["dtype"] = dtype_name(v.dtype);
    vertical["codec"] = codec_json(v.codec, kManifestVersionGeometry);
  }
  json j{{"horizontal", std::move(horizontal)},
         {"vertical", std::move(vertical)},
         {"orientation", g.orientation}};
  if (g.surface) j["surface"] = json{{"variable", g.surface->variable}, {"units", g.surface->units}};
  return j;
}

GridGeometry geometry_from_json(const json& j, std::size_t z_size, std::string_view what) {
  const std::string where = fmt::format("{}: geometry", what);
  if (!j.is_object()) throw make_error(ErrorCode::kCorrupt, "{}: is not an object", where);
  only_keys(j, {"horizontal", "vertical", "surface", "orientation"}, where);
  GridGeometry g;
  g.horizontal = horizontal_from_json(object(j, "horizontal", where), what);
  g.vertical = vertical_from_json(object(j, "vertical", where), what);
  if (j.contains("surface")) {
    const std::string at = fmt::format("{}: geometry.surface", what);
    const json& s = object(j, "surface", where);
    only_keys(s, {"variable", "units"}, at);
    g.surface = SurfaceGeometry{get<std::string>(s, "variable", at), get<std::string>(s, "units", at)};
  }
  g.orientation = get<int>(j, "orientation", where);
  check_geometry(g, z_size, what, ErrorCode::kCorrupt);
  return g;
}

}  // namespace strielad::format
