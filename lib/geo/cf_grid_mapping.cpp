// SPDX-License-Identifier: Apache-2.0
#include "geo/cf_grid_mapping.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <optional>
#include <vector>

#include "core/error.h"
#include "grid/units.h"

namespace strielad::geo {
namespace {

using nlohmann::json;

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  while (!out.empty() && std::isspace(static_cast<unsigned char>(out.back()))) out.pop_back();
  while (!out.empty() && std::isspace(static_cast<unsigned char>(out.front()))) out.erase(0, 1);
  return out;
}

std::string num(double v) { return fmt::format("{:.17g}", v); }

// Reads the mapping's numeric attributes with errors naming them.
class Parameters {
 public:
  Parameters(const GridMapping& m, std::string_view what) : m_(m), what_(what) {}

  // Every value of a numeric attribute (one, or an array); empty when absent.
  std::vector<double> values(std::string_view key) const {
    const auto it = m_.attributes.find(std::string(key));
    if (it == m_.attributes.end()) return {};
    std::vector<double> out;
    auto take = [&](const json& v) {
      if (!v.is_number()) {
        throw make_error(ErrorCode::kInvalidInput,
                         "{}: grid mapping '{}' ({}): attribute '{}' is not a number", what_,
                         m_.variable, m_.name, key);
      }
      const double d = v.get<double>();
      if (!std::isfinite(d)) {
        throw make_error(ErrorCode::kInvalidInput,
                         "{}: grid mapping '{}' ({}): attribute '{}' is not finite ({})", what_,
                         m_.variable, m_.name, key, d);
      }
      out.push_back(d);
    };
    if (it->is_array()) {
      for (const json& v : *it) take(v);
    } else {
      take(*it);
    }
    if (out.empty()) {
      throw make_error(ErrorCode::kInvalidInput, "{}: grid mapping '{}' ({}): attribute '{}' is empty",
                       what_, m_.variable, m_.name, key);
    }
    return out;
  }

  std::optional<double> optional(std::string_view key) const {
    const auto v = values(key);
    if (v.empty()) return std::nullopt;
    if (v.size() != 1) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: grid mapping '{}' ({}): attribute '{}' has {} values, expected one",
                       what_, m_.variable, m_.name, key, v.size());
    }
    return v[0];
  }

  double required(std::string_view key) const {
    const auto v = optional(key);
    if (!v) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: grid mapping '{}' ({}) lacks the attribute '{}' it needs", what_,
                       m_.variable, m_.name, key);
    }
    return *v;
  }

  // The first of `keys` present (CF allows alternative names for some parameters).
  double required_one_of(std::initializer_list<std::string_view> keys) const {
    for (std::string_view k : keys) {
      if (const auto v = optional(k)) return *v;
    }
    std::string names;
    for (std::string_view k : keys) names += fmt::format("{}'{}'", names.empty() ? "" : " or ", k);
    throw make_error(ErrorCode::kInvalidInput, "{}: grid mapping '{}' ({}) lacks the attribute {}",
                     what_, m_.variable, m_.name, names);
  }

  double latitude(std::string_view key, double v) const {
    if (v < -90.0 || v > 90.0) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: grid mapping '{}' ({}): attribute '{}' = {} is not a latitude", what_,
                       m_.variable, m_.name, key, v);
    }
    return v;
  }
  double required_latitude(std::string_view key) const { return latitude(key, required(key)); }

  // lat_1 [lat_2] from standard_parallel (one or two values).
  std::string standard_parallels() const {
    const auto v = values("standard_parallel");
    if (v.empty() || v.size() > 2) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: grid mapping '{}' ({}): attribute 'standard_parallel' needs one or two "
                       "values (has {})",
                       what_, m_.variable, m_.name, v.size());
    }
    std::string out = fmt::format(" +lat_1={}", num(latitude("standard_parallel", v[0])));
    if (v.size() == 2) out += fmt::format(" +lat_2={}", num(latitude("standard_parallel", v[1])));
    return out;
  }

  // +lat_ts from standard_parallel, or +k_0 from `scale_key`: exactly one of them.
  std::string true_scale(std::string_view scale_key) const {
    const auto sp = optional("standard_parallel");
    const auto k = optional(scale_key);
    if (sp && k) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: grid mapping '{}' ({}) has both 'standard_parallel' and '{}'; CF "
                       "allows one of them",
                       what_, m_.variable, m_.name, scale_key);
    }
    if (sp) return fmt::format(" +lat_ts={}", num(latitude("standard_parallel", *sp)));
    if (k) return fmt::format(" +k_0={}", num(positive(scale_key, *k)));
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: grid mapping '{}' ({}) lacks 'standard_parallel' or '{}'", what_,
                     m_.variable, m_.name, scale_key);
  }

  double positive(std::string_view key, double v) const {
    if (!(v > 0)) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: grid mapping '{}' ({}): attribute '{}' = {} must be above 0", what_,
                       m_.variable, m_.name, key, v);
    }
    return v;
  }

  std::string false_origin() const {
    return fmt::format(" +x_0={} +y_0={}", num(optional("false_easting").value_or(0.0)),
                       num(optional("false_northing").value_or(0.0)));
  }

  // The figure of the Earth (header comment).
  std::string figure() const {
    if (const auto r = optional("earth_radius")) return fmt::format(" +R={}", num(positive("earth_radius", *r)));
    const auto a = optional("semi_major_axis");
    const auto b = optional("semi_minor_axis");
    const auto rf = optional("inverse_flattening");
    if (!a) {
      if (b || rf) {
        throw make_error(ErrorCode::kInvalidInput,
                         "{}: grid mapping '{}' ({}) has '{}' without 'semi_major_axis'", what_,
                         m_.variable, m_.name, b ? "semi_minor_axis" : "inverse_flattening");
      }
      return " +ellps=WGS84";
    }
    positive("semi_major_axis", *a);
    if (b) return fmt::format(" +a={} +b={}", num(*a), num(positive("semi_minor_axis", *b)));
    if (rf && *rf != 0) return fmt::format(" +a={} +rf={}", num(*a), num(positive("inverse_flattening", *rf)));
    return fmt::format(" +R={}", num(*a));
  }

 private:
  const GridMapping& m_;
  std::string_view what_;
};

constexpr std::array<std::string_view, 13> kSupported{
    "rotated_latitude_longitude",   "lambert_conformal_conic",      "polar_stereographic",
    "stereographic",                "transverse_mercator",          "mercator",
    "lambert_azimuthal_equal_area", "albers_conical_equal_area",    "azimuthal_equidistant",
    "orthographic",                 "lambert_cylindrical_equal_area", "sinusoidal",
    "latitude_longitude"};

}  // namespace

std::string_view supported_grid_mappings() {
  static const std::string list = [] {
    std::string s;
    for (std::string_view n : kSupported) s += fmt::format("{}{}", s.empty() ? "" : ", ", n);
    return s;
  }();
  return list;
}

namespace {

Error axis_units_error(const Axis& a, std::string_view needs, const GridMapping& mapping,
                       std::string_view what) {
  return make_error(ErrorCode::kUnsupported,
                    "{}: axis '{}' has units '{}', but grid mapping '{}' ({}) needs {}", what,
                    a.name, a.units, mapping.variable, mapping.name, needs);
}

void check_degree_axes(const Axis& x, const Axis& y, const GridMapping& mapping,
                       std::string_view what) {
  for (const Axis* a : {&x, &y}) {
    if (!is_degree_units(a->units)) throw axis_units_error(*a, "degrees", mapping, what);
  }
}

// Metres per unit of projection axes x and y, which must have the same length unit.
double projection_axis_metres(const Axis& x, const Axis& y, const GridMapping& mapping,
                              std::string_view what) {
  const auto mx = metres_per_length_unit(x.units), my = metres_per_length_unit(y.units);
  if (!mx) throw axis_units_error(x, "a length (m or km)", mapping, what);
  if (!my) throw axis_units_error(y, "a length (m or km)", mapping, what);
  if (*mx != *my) {
    throw make_error(ErrorCode::kUnsupported,
                     "{}: axes '{}' ({}) and '{}' ({}) of grid mapping '{}' have different units",
                     what, x.name, x.units, y.name, y.units, mapping.variable);
  }
  return *mx;
}

// Rotated-pole longitude and latitude to geographic degrees.
std::string rotated_pole_pipeline(const Parameters& p) {
  const double pole_lat = p.required_latitude("grid_north_pole_latitude");
  const double pole_lon = p.required("grid_north_pole_longitude");
  const double grid_lon = p.optional("north_pole_grid_longitude").value_or(0.0);
  return fmt::format(
      "+proj=pipeline +step +proj=unitconvert +xy_in=deg +xy_out=rad "
      "+step +inv +proj=ob_tran +o_proj=longlat +o_lat_p={} +o_lon_p={} +lon_0={} "
      "+step +proj=unitconvert +xy_in=rad +xy_out=deg",
      num(pole_lat), num(grid_lon), num(180.0 + pole_lon));
}

// The PROJ projection of a supported projected grid mapping `name`, without false origin
// and figure of the Earth.
std::string projection_definition(const std::string& name, const Parameters& p,
                                  const GridMapping& mapping, std::string_view what) {
  std::string projection;
  auto origin_latitude = [&] {
    return fmt::format(" +lat_0={}", num(p.required_latitude("latitude_of_projection_origin")));
  };
  if (name == "lambert_conformal_conic") {
    projection = "+proj=lcc" + p.standard_parallels() + origin_latitude() +
                 fmt::format(" +lon_0={}", num(p.required("longitude_of_central_meridian")));
  } else if (name == "albers_conical_equal_area") {
    projection = "+proj=aea" + p.standard_parallels() + origin_latitude() +
                 fmt::format(" +lon_0={}", num(p.required("longitude_of_central_meridian")));
  } else if (name == "polar_stereographic") {
    const double lat = p.required_latitude("latitude_of_projection_origin");
    if (lat != 90.0 && lat != -90.0) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: grid mapping '{}' (polar_stereographic): latitude_of_projection_origin "
                       "is {}; a polar stereographic projection has +90 or -90",
                       what, mapping.variable, lat);
    }
    projection = "+proj=stere" + origin_latitude() +
                 fmt::format(" +lon_0={}", num(p.required_one_of({"straight_vertical_longitude_from_pole",
                                                                  "longitude_of_projection_origin"}))) +
                 p.true_scale("scale_factor_at_projection_origin");
  } else if (name == "stereographic") {
    projection = "+proj=stere" + origin_latitude() +
                 fmt::format(" +lon_0={} +k_0={}", num(p.required("longitude_of_projection_origin")),
                             num(p.positive("scale_factor_at_projection_origin",
                                            p.optional("scale_factor_at_projection_origin").value_or(1.0))));
  } else if (name == "transverse_mercator") {
    projection = "+proj=tmerc" + origin_latitude() +
                 fmt::format(" +lon_0={} +k_0={}", num(p.required("longitude_of_central_meridian")),
                             num(p.positive("scale_factor_at_central_meridian",
                                            p.required("scale_factor_at_central_meridian"))));
  } else if (name == "mercator") {
    projection = "+proj=merc" +
                 fmt::format(" +lon_0={}", num(p.required("longitude_of_projection_origin"))) +
                 p.true_scale("scale_factor_at_projection_origin");
  } else if (name == "lambert_azimuthal_equal_area") {
    projection = "+proj=laea" + origin_latitude() +
                 fmt::format(" +lon_0={}", num(p.required("longitude_of_projection_origin")));
  } else if (name == "azimuthal_equidistant") {
    projection = "+proj=aeqd" + origin_latitude() +
                 fmt::format(" +lon_0={}", num(p.required("longitude_of_projection_origin")));
  } else if (name == "orthographic") {
    projection = "+proj=ortho" + origin_latitude() +
                 fmt::format(" +lon_0={}", num(p.required("longitude_of_projection_origin")));
  } else if (name == "lambert_cylindrical_equal_area") {
    projection = "+proj=cea" +
                 fmt::format(" +lon_0={}", num(p.required("longitude_of_central_meridian"))) +
                 p.true_scale("scale_factor_at_projection_origin");
  } else if (name == "sinusoidal") {
    projection = "+proj=sinu" +
                 fmt::format(" +lon_0={}", num(p.required("longitude_of_central_meridian")));
  }
  return projection;
}

}  // namespace

std::string cf_grid_mapping_proj(const GridMapping& mapping, const Axis& x, const Axis& y,
                                 std::string_view what) {
  const std::string name = lower(mapping.name);
  if (std::find(kSupported.begin(), kSupported.end(), name) == kSupported.end()) {
    throw make_error(ErrorCode::kUnsupported,
                     "{}: grid mapping '{}' has grid_mapping_name '{}', which this version cannot "
                     "place (it places: {})",
                     what, mapping.variable, mapping.name, supported_grid_mappings());
  }
  const Parameters p(mapping, what);
  if (name == "latitude_longitude") {
    check_degree_axes(x, y, mapping, what);
    p.figure();  // validates the attributes; the axes are used as they are
    return "";
  }
  if (name == "rotated_latitude_longitude") {
    check_degree_axes(x, y, mapping, what);
    return rotated_pole_pipeline(p);
  }
  const double metres = projection_axis_metres(x, y, mapping, what);
  const std::string projection = projection_definition(name, p, mapping, what);
  std::string pipeline = "+proj=pipeline";
  if (metres != 1.0) pipeline += " +step +proj=unitconvert +xy_in=km +xy_out=m";
  pipeline += " +step +inv " + projection + p.false_origin() + p.figure();
  pipeline += " +step +proj=unitconvert +xy_in=rad +xy_out=deg";
  return pipeline;
}

}  // namespace strielad::geo
