// SPDX-License-Identifier: Apache-2.0
// Deciding what a dimension is (longitude, latitude, vertical, time) from the CF/COARDS
// metadata of its coordinate variable, and what kind of vertical coordinate it is.
// Pure functions over attribute values: no netCDF calls.
#pragma once

#include <string>
#include <string_view>

#include "grid/axis.h"

namespace strielad::ingest {

enum class DimensionRole { kUnknown, kTime, kVertical, kLatitude, kLongitude };

std::string_view dimension_role_name(DimensionRole role) noexcept;

// The attributes of a coordinate variable that identify its dimension.
struct CoordinateAttributes {
  std::string name;  // the coordinate variable's (= the dimension's) name
  std::string axis, standard_name, units, long_name, positive;
  bool has_formula_terms = false;
};

// In order of precedence: `axis` (X/Y/Z/T), `standard_name`, `units`, `positive`, the
// name, and whether the dimension is the unlimited one. kUnknown when nothing tells; the
// caller then falls back to the COARDS position.
DimensionRole detect_dimension_role(const CoordinateAttributes& coordinate, bool unlimited);

// Model level whenever the coordinate has formula_terms (whatever else it says); else
// pressure (Pa, hPa, mbar, millibars, atm or standard_name air_pressure), height (m, km
// or standard_name height/altitude), model level (atmosphere_*_coordinate standard
// names, model_level_number, hybrid/sigma units) or other.
AxisKind detect_vertical_kind(const CoordinateAttributes& coordinate);

bool is_longitude_units(std::string_view units);
bool is_latitude_units(std::string_view units);
bool is_time_units(std::string_view units);  // "<unit> since <date>"
bool is_pressure_units(std::string_view units);
bool is_length_units(std::string_view units);

// True for variables that look like longitudes or latitudes (standard_name, units or a
// conventional name), used to recognise auxiliary coordinates of unstructured and
// curvilinear grids.
bool looks_like_longitude(const CoordinateAttributes& variable);
bool looks_like_latitude(const CoordinateAttributes& variable);

}  // namespace strielad::ingest
