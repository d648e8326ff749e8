// SPDX-License-Identifier: Apache-2.0
#include "ingest/cf_axis_detection.h"

#include <algorithm>
#include <array>
#include <cctype>

namespace strielad::ingest {
namespace {

std::string lower_trimmed(std::string_view text) {
  std::size_t b = 0, e = text.size();
  while (b < e && std::isspace(static_cast<unsigned char>(text[b]))) ++b;
  while (e > b && std::isspace(static_cast<unsigned char>(text[e - 1]))) --e;
  std::string out(text.substr(b, e - b));
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

template <std::size_t N>
bool one_of(std::string_view value, const std::array<std::string_view, N>& set) {
  return std::find(set.begin(), set.end(), value) != set.end();
}

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }
bool ends_with(std::string_view s, std::string_view p) {
  return s.size() >= p.size() && s.substr(s.size() - p.size()) == p;
}
bool contains(std::string_view s, std::string_view p) { return s.find(p) != std::string_view::npos; }

// "lev_2" -> "lev", "height2" -> "height": CDO and others number repeated axes.
std::string name_stem(std::string_view name) {
  std::string s = lower_trimmed(name);
  while (!s.empty() && std::isdigit(static_cast<unsigned char>(s.back()))) s.pop_back();
  while (!s.empty() && (s.back() == '_' || s.back() == '-')) s.pop_back();
  return s.empty() ? lower_trimmed(name) : s;
}

constexpr std::array<std::string_view, 7> kLongitudeNames{
    "lon", "longitude", "rlon", "glon", "long", "nav_lon", "longitudes"};
constexpr std::array<std::string_view, 7> kLatitudeNames{
    "lat", "latitude", "rlat", "glat", "nav_lat", "latitudes", "lats"};
constexpr std::array<std::string_view, 5> kTimeNames{"time", "frtime", "times", "valid_time",
                                                     "t"};
constexpr std::array<std::string_view, 20> kVerticalNames{
    "lev",      "level",         "levels",    "levelist", "plev",     "ilev",   "mlev",
    "height",   "alt",           "altitude",  "z",        "depth",    "pres",   "pressure",
    "isobaric", "isobaricinhpa", "bottom_top", "sigma",   "hybrid",   "zlev"};

constexpr std::array<std::string_view, 9> kVerticalStandardNames{
    "air_pressure",           "height",       "altitude", "depth", "model_level_number",
    "geopotential_height",    "air_potential_temperature", "height_above_mean_sea_level",
    "height_above_reference_ellipsoid"};

bool is_vertical_standard_name(std::string_view sn) {
  if (one_of(sn, kVerticalStandardNames)) return true;
  if ((starts_with(sn, "atmosphere_") || starts_with(sn, "ocean_")) &&
      ends_with(sn, "_coordinate")) {
    return true;
  }
  return starts_with(sn, "height_above_");
}

}  // namespace

std::string_view dimension_role_name(DimensionRole role) noexcept {
  switch (role) {
    case DimensionRole::kTime: return "time";
    case DimensionRole::kVertical: return "vertical";
    case DimensionRole::kLatitude: return "latitude";
    case DimensionRole::kLongitude: return "longitude";
    case DimensionRole::kUnknown: return "unknown";
  }
  return "unknown";
}

bool is_longitude_units(std::string_view units) {
  static constexpr std::array<std::string_view, 6> kUnits{
      "degrees_east", "degree_east", "degrees_e", "degree_e", "degreese", "degreee"};
  return one_of(lower_trimmed(units), kUnits);
}

bool is_latitude_units(std::string_view units) {
  static constexpr std::array<std::string_view, 6> kUnits{
      "degrees_north", "degree_north", "degrees_n", "degree_n", "degreesn", "degreen"};
  return one_of(lower_trimmed(units), kUnits);
}

bool is_time_units(std::string_view units) {
  const std::string u = lower_trimmed(units);
  const auto pos = u.find(" since ");
  return pos != std::string::npos && pos > 0 && pos + 7 < u.size();
}

bool is_pressure_units(std::string_view units) {
  static constexpr std::array<std::string_view, 14> kUnits{
      "pa",          "hpa",     "kpa",     "mbar",     "millibar", "millibars", "mb",
      "hectopascal", "hectopascals", "pascal", "pascals", "atm",      "bar",       "bars"};
  return one_of(lower_trimmed(units), kUnits);
}

bool is_length_units(std::string_view units) {
  static constexpr std::array<std::string_view, 10> kUnits{
      "m",      "km",     "meter",     "meters",     "metre",
      "metres", "kilometer", "kilometers", "kilometre", "kilometres"};
  return one_of(lower_trimmed(units), kUnits);
}

DimensionRole detect_dimension_role(const CoordinateAttributes& c, bool unlimited) {
  const std::string axis = lower_trimmed(c.axis);
  if (axis == "x") return DimensionRole::kLongitude;
  if (axis == "y") return DimensionRole::kLatitude;
  if (axis == "z") return DimensionRole::kVertical;
  if (axis == "t") return DimensionRole::kTime;

  const std::string sn = lower_trimmed(c.standard_name);
  if (sn == "longitude" || sn == "grid_longitude" || sn == "projection_x_coordinate") {
    return DimensionRole::kLongitude;
  }
  if (sn == "latitude" || sn == "grid_latitude" || sn == "projection_y_coordinate") {
    return DimensionRole::kLatitude;
  }
  if (sn == "time" || sn == "forecast_reference_time" || sn == "forecast_period") {
    return DimensionRole::kTime;
  }
  if (is_vertical_standard_name(sn)) return DimensionRole::kVertical;

  if (is_longitude_units(c.units)) return DimensionRole::kLongitude;
  if (is_latitude_units(c.units)) return DimensionRole::kLatitude;
  if (is_time_units(c.units)) return DimensionRole::kTime;
  if (is_pressure_units(c.units) || is_length_units(c.units)) return DimensionRole::kVertical;

  const std::string positive = lower_trimmed(c.positive);
  if (positive == "up" || positive == "down") return DimensionRole::kVertical;

  const std::string stem = name_stem(c.name);
  if (one_of(stem, kLongitudeNames)) return DimensionRole::kLongitude;
  if (one_of(stem, kLatitudeNames)) return DimensionRole::kLatitude;
  if (one_of(stem, kTimeNames)) return DimensionRole::kTime;
  if (one_of(stem, kVerticalNames)) return DimensionRole::kVertical;

  if (unlimited) return DimensionRole::kTime;
  return DimensionRole::kUnknown;
}

AxisKind detect_vertical_kind(const CoordinateAttributes& c) {
  // A parametric coordinate: its values are no heights or pressures, whatever its
  // standard_name or units claim; the formula places the samples.
  if (c.has_formula_terms) return AxisKind::kModelLevel;
  const std::string sn = lower_trimmed(c.standard_name);
  if (sn == "air_pressure") return AxisKind::kPressure;
  if (sn == "height" || sn == "altitude" || starts_with(sn, "height_above_")) {
    return AxisKind::kHeight;
  }
  if (sn == "model_level_number" ||
      ((starts_with(sn, "atmosphere_") || starts_with(sn, "ocean_")) &&
       ends_with(sn, "_coordinate"))) {
    return AxisKind::kModelLevel;
  }
  if (sn == "depth") return AxisKind::kOther;  // positive down, not a height
  if (is_pressure_units(c.units)) return AxisKind::kPressure;
  if (is_length_units(c.units)) {
    return lower_trimmed(c.positive) == "down" ? AxisKind::kOther : AxisKind::kHeight;
  }
  const std::string units = lower_trimmed(c.units);
  const std::string long_name = lower_trimmed(c.long_name);
  for (const std::string* text : {&units, &long_name}) {
    if (contains(*text, "hybrid") || contains(*text, "sigma")) return AxisKind::kModelLevel;
  }
  if (units == "model_level_number" || long_name == "model level number") {
    return AxisKind::kModelLevel;
  }
  return AxisKind::kOther;
}

bool looks_like_longitude(const CoordinateAttributes& v) {
  const std::string sn = lower_trimmed(v.standard_name);
  if (sn == "longitude") return true;
  if (is_longitude_units(v.units)) return true;
  const std::string stem = name_stem(v.name);
  return one_of(stem, kLongitudeNames) || stem == "clon" || stem == "xlong" ||
         stem == "vlon" || stem == "elon";
}

bool looks_like_latitude(const CoordinateAttributes& v) {
  const std::string sn = lower_trimmed(v.standard_name);
  if (sn == "latitude") return true;
  if (is_latitude_units(v.units)) return true;
  const std::string stem = name_stem(v.name);
  return one_of(stem, kLatitudeNames) || stem == "clat" || stem == "xlat" ||
         stem == "vlat" || stem == "elat";
}

}  // namespace strielad::ingest
