// SPDX-License-Identifier: Apache-2.0
#include "ingest/file_scan.h"

#include <fmt/format.h>
#include <netcdf.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <mutex>
#include <set>
#include <tuple>

#include "ingest/cf_attributes.h"
#include "ingest/cf_axis_detection.h"
#include "ingest/grid_mapping_reader.h"
#include "ingest/horizontal_axes.h"
#include "ingest/ln_pressure_axis.h"
#include "ingest/netcdf_call.h"
#include "ingest/netcdf_file.h"
#include "ingest/source_file.h"
#include "ingest/wrf_grid_reader.h"
#include "ingest/wrf_scan.h"

namespace strielad::ingest {

const ScannedVariable* ScannedFile::find(std::string_view name) const {
  for (const auto& v : variables) {
    if (v.name == name) return &v;
  }
  return nullptr;
}

namespace {

constexpr std::string_view kRemapAdvice =
    "only logically rectangular grids are supported — remap it first (e.g. cdo remapcon)";
constexpr std::string_view kCurvilinearAdvice =
    "a grid placed by 2-D latitude/longitude is converted only when the variable's coordinates "
    "attribute names a longitude and a latitude the file holds, over exactly its last two "
    "dimensions, which have no coordinate variables — otherwise remap it to a regular or "
    "projected grid first (e.g. cdo remapbil)";

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

CoordinateAttributes read_coordinate_attributes(int grpid, int varid) {
  CoordinateAttributes a;
  a.name = variable_name(grpid, varid);
  a.axis = text_attribute_or_empty(grpid, varid, "axis");
  a.standard_name = text_attribute_or_empty(grpid, varid, "standard_name");
  a.units = text_attribute_or_empty(grpid, varid, "units");
  a.long_name = text_attribute_or_empty(grpid, varid, "long_name");
  a.positive = text_attribute_or_empty(grpid, varid, "positive");
  a.has_formula_terms = has_attribute(grpid, varid, "formula_terms");
  return a;
}

std::string join(const std::vector<std::string>& words, std::string_view sep) {
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) out += sep;
    out += words[i];
  }
  return out;
}

// Whether group `grpid` or one of its ancestors has a variable `name`.
bool variable_in_scope(int grpid, const std::string& name) {
  for (std::optional<int> g = grpid; g; g = parent_group(*g)) {
    int varid = -1;
    if (nc_inq_varid(*g, name.c_str(), &varid) == NC_NOERR) return true;
  }
  return false;
}

// Whether variable `name` (in group `grpid` or an ancestor) has strictly monotonic values
// once a wrapped longitude is unwrapped.
bool monotonic_in_scope(int grpid, const std::string& name) {
  for (std::optional<int> g = grpid; g; g = parent_group(*g)) {
    int varid = -1;
    if (nc_inq_varid(*g, name.c_str(), &varid) != NC_NOERR) continue;
    Axis a;
    a.name = name;
    a.values = read_all_as_double(*g, varid, name);
    unwrap_longitudes(a.values);
    try {
      check_axis_values(a, name);
      return true;
    } catch (const Error&) {
      return false;
    }
  }
  return false;
}

bool is_unstructured_dimension_name(std::string_view name) {
  static constexpr std::array<std::string_view, 14> kNames{
      "ncells", "ncell",  "cell",  "cells",     "ncol",        "ncols",           "nod2",
      "nod2d",  "nelem",  "elem",  "nodes",     "nmesh2d_face", "mesh2d_nfaces", "nvertex"};
  const std::string l = lower(name);
  return std::find(kNames.begin(), kNames.end(), l) != kNames.end();
}

struct Coordinate {
  CoordinateAttributes attrs;
  std::string calendar;
  DimensionRole role = DimensionRole::kUnknown;
  std::vector<double> values;
};

struct LonLatVariable {
  std::string name;
  std::vector<int> dimids;
};

constexpr std::string_view k3dOnly =
    "only 3D variables (vertical, lat, lon), optionally with a leading time dimension, are "
    "supported";

// The lon/lat variables that could place a variable: those its `coordinates` attribute
// names (else every one in scope), and the names it gives that the file does not hold.
struct LonLatCandidates {
  std::vector<LonLatVariable> variables;
  std::vector<std::string> absent;
};

// A data variable with its dimensions and each dimension's coordinate variable, if any.
struct VariableDimensions {
  int grpid = 0;
  int varid = 0;
  std::string name;
  std::vector<int> dimids;
  std::vector<std::optional<VariableRef>> coords;
};

// The 2-D longitude and latitude variables that place a variable on a curvilinear grid.
struct CurvilinearCoordinates {
  VariableRef lon, lat;
  std::string lon_name, lat_name;
};

// Why a variable is not converted, and which class that puts it in.
struct Rejection {
  VariableClass klass;
  Error error;
};

class FileScanner {
 public:
  FileScanner(std::string display, int ncid) : file_(std::move(display)), ncid_(ncid) {
    for (int g : all_groups(ncid_)) {
      const int nvars = variable_count(g);
      for (int v = 0; v < nvars; ++v) {
        for (const char* attr : {"bounds", "coordinates", "climatology"}) {
          for (auto& word : split_words(text_attribute_or_empty(g, v, attr))) {
            auxiliary_.insert(std::move(word));
          }
        }
      }
    }
  }

  std::vector<ScannedVariable> scan_all() {
    std::vector<ScannedVariable> out;
    for (int g : all_groups(ncid_)) {
      const std::string path = group_path(g);
      const std::string prefix = path.empty() ? std::string() : path + "/";
      const int nvars = variable_count(g);
      for (int v = 0; v < nvars; ++v) out.push_back(scan_variable(g, v, prefix));
    }
    return out;
  }

 private:
  ScannedVariable scan_variable(int grpid, int varid, const std::string& prefix);
  const Coordinate& coordinate(const VariableRef& ref, bool unlimited);
  std::optional<Error> detect_unstructured(const VariableDimensions& var);
  LonLatCandidates lonlat_candidates(int grpid, int varid);
  std::optional<Error> unstructured_grid_error(const VariableDimensions& var,
                                               const std::vector<LonLatVariable>& candidates);
  std::optional<Error> absent_curvilinear_coordinates_error(const VariableDimensions& var,
                                                            const std::vector<std::string>& absent);
  std::optional<Error> curvilinear_grid_error(const VariableDimensions& var,
                                              const std::vector<LonLatVariable>& candidates);
  std::optional<CurvilinearCoordinates> curvilinear_coordinates(const VariableDimensions& var);
  ScannedVariable scan_curvilinear(ScannedVariable sv, const VariableDimensions& var,
                                   const CurvilinearCoordinates& coordinates);
  std::shared_ptr<const CurvilinearGrid> curvilinear_grid(const CurvilinearCoordinates& c,
                                                          std::size_t nx, std::size_t ny,
                                                          const std::string& what);
  std::vector<DimensionRole> dimension_roles(const VariableDimensions& var);
  std::optional<Rejection> check_dimension_roles(const ScannedVariable& sv,
                                                 const std::vector<DimensionRole>& roles);
  Axis coordinate_axis(const VariableRef& ref, AxisKind kind);
  void read_axes(ScannedVariable& sv, const VariableDimensions& var);
  // The time coordinate of a 4-D variable (its first dimension), its values checked.
  TimeCoordinate time_coordinate(const VariableDimensions& var);
  const std::vector<LonLatVariable>& lonlat_variables(int grpid);
  std::optional<VariableRef> paired_coordinate(int grpid, int dimid);
  std::optional<LonLatVariable> lonlat_variable(int grpid, const std::string& name);

  std::string file_;
  int ncid_;
  std::set<std::string> auxiliary_;
  std::set<std::string> logged_;  // notes on horizontal axes, logged once each
  std::map<std::pair<int, int>, Coordinate> coordinates_;
  std::map<int, std::vector<LonLatVariable>> lonlat_by_group_;
  std::map<std::pair<int, int>, std::optional<VariableRef>> paired_;
  // By (lon group, lon varid, lat group, lat varid).
  std::map<std::tuple<int, int, int, int>, std::shared_ptr<const CurvilinearGrid>> curvilinear_;
};

const Coordinate& FileScanner::coordinate(const VariableRef& ref, bool unlimited) {
  const auto key = std::make_pair(ref.grpid, ref.varid);
  if (auto it = coordinates_.find(key); it != coordinates_.end()) return it->second;
  Coordinate c;
  c.attrs = read_coordinate_attributes(ref.grpid, ref.varid);
  c.calendar = text_attribute_or_empty(ref.grpid, ref.varid, "calendar");
  c.role = detect_dimension_role(c.attrs, unlimited);
  if (is_numeric_type(variable_type(ref.grpid, ref.varid))) {
    c.values = read_all_as_double(ref.grpid, ref.varid,
                                  fmt::format("{}: coordinate variable '{}'", file_, c.attrs.name));
  }
  return coordinates_.emplace(key, std::move(c)).first->second;
}

const std::vector<LonLatVariable>& FileScanner::lonlat_variables(int grpid) {
  if (auto it = lonlat_by_group_.find(grpid); it != lonlat_by_group_.end()) return it->second;
  std::vector<LonLatVariable> found;
  const int nvars = variable_count(grpid);
  for (int v = 0; v < nvars; ++v) {
    const auto dimids = variable_dimids(grpid, v);
    const auto attrs = read_coordinate_attributes(grpid, v);
    if (dimids.empty()) continue;
    if (dimids.size() == 1 && dimension_name(grpid, dimids[0]) == attrs.name) continue;
    if (looks_like_longitude(attrs) || looks_like_latitude(attrs)) {
      found.push_back({attrs.name, dimids});
    }
  }
  return lonlat_by_group_.emplace(grpid, std::move(found)).first->second;
}

std::optional<LonLatVariable> FileScanner::lonlat_variable(int grpid, const std::string& name) {
  for (std::optional<int> g = grpid; g; g = parent_group(*g)) {
    int varid = -1;
    if (nc_inq_varid(*g, name.c_str(), &varid) != NC_NOERR) continue;
    const auto attrs = read_coordinate_attributes(*g, varid);
    if (!looks_like_longitude(attrs) && !looks_like_latitude(attrs)) return std::nullopt;
    return LonLatVariable{name, variable_dimids(*g, varid)};
  }
  return std::nullopt;
}

// A dimension without a coordinate variable of its name, and exactly one 1-D numeric
// variable over it (in its group or an ancestor) whose axis, standard_name, units or
// positive attribute says what it is and whose values are strictly monotonic: that
// variable is the dimension's coordinate (ex01B1_uv300.hs.nc has lon(longitude),
// lat(latitude), plvl(level)). Logged once per dimension; two candidates, or values that
// are not monotonic (an unstructured grid's cell longitudes), pair nothing.
std::optional<VariableRef> FileScanner::paired_coordinate(int grpid, int dimid) {
  const auto key = std::make_pair(grpid, dimid);
  if (auto it = paired_.find(key); it != paired_.end()) return it->second;
  const std::string dim = dimension_name(grpid, dimid);
  std::vector<VariableRef> found;
  for (std::optional<int> g = grpid; g; g = parent_group(*g)) {
    const int nvars = variable_count(*g);
    for (int v = 0; v < nvars; ++v) {
      const auto dims = variable_dimids(*g, v);
      if (dims.size() != 1 || dims[0] != dimid || !is_numeric_type(variable_type(*g, v))) continue;
      const CoordinateAttributes attrs = read_coordinate_attributes(*g, v);
      CoordinateAttributes without_name = attrs;
      without_name.name.clear();
      if (detect_dimension_role(without_name, false) == DimensionRole::kUnknown) continue;
      found.push_back(VariableRef{*g, v});
    }
  }
  std::optional<VariableRef> pair;
  if (found.size() == 1) {
    Axis a;
    a.name = variable_name(found[0].grpid, found[0].varid);
    a.values = read_all_as_double(found[0].grpid, found[0].varid,
                                  fmt::format("{}: variable '{}'", file_, a.name));
    std::vector<double> unwrapped = a.values;
    unwrap_longitudes(unwrapped);
    a.values = unwrapped;
    bool monotonic = true;
    try {
      check_axis_values(a, file_);
    } catch (const Error&) {
      monotonic = false;
    }
    if (monotonic) {
      pair = found[0];
      spdlog::info("{}: dimension '{}' has no coordinate variable of its name; using '{}', the "
                   "only 1-D variable over it that says what it is (rename it to '{}' to make "
                   "this explicit: ncrename -v {},{})",
                   file_, dim, a.name, dim, a.name, dim);
    }
  }
  return paired_.emplace(key, pair).first->second;
}

// A dimension is horizontally unresolved when it has no coordinate variable, or one
// that is not a longitude or latitude (projection x/y in metres, for instance).
bool horizontally_unresolved(const std::optional<VariableRef>& coord) {
  if (!coord) return true;
  const auto attrs = read_coordinate_attributes(coord->grpid, coord->varid);
  const std::string sn = lower(attrs.standard_name);
  const std::string axis = lower(attrs.axis);
  return !(looks_like_longitude(attrs) || looks_like_latitude(attrs) || sn == "grid_longitude" ||
           sn == "grid_latitude" || sn == "projection_x_coordinate" ||
           sn == "projection_y_coordinate" || axis == "x" || axis == "y");
}

std::optional<std::size_t> index_of(const std::vector<int>& dimids, int dimid) {
  for (std::size_t i = 0; i < dimids.size(); ++i) {
    if (dimids[i] == dimid) return i;
  }
  return std::nullopt;
}

LonLatCandidates FileScanner::lonlat_candidates(int grpid, int varid) {
  LonLatCandidates out;
  for (const auto& word : split_words(text_attribute_or_empty(grpid, varid, "coordinates"))) {
    if (auto v = lonlat_variable(grpid, word)) {
      out.variables.push_back(*v);
    } else if (!variable_in_scope(grpid, word)) {
      out.absent.push_back(word);
    }
  }
  if (out.variables.empty()) {
    for (std::optional<int> g = grpid; g; g = parent_group(*g)) {
      for (const auto& v : lonlat_variables(*g)) out.variables.push_back(v);
    }
  }
  return out;
}

// Unstructured: 1D lon/lat variables over a dimension without coordinate variable.
std::optional<Error> FileScanner::unstructured_grid_error(
    const VariableDimensions& var, const std::vector<LonLatVariable>& candidates) {
  for (std::size_t i = 0; i < var.dimids.size(); ++i) {
    if (var.coords[i]) continue;
    std::vector<std::string> names;
    for (const auto& c : candidates) {
      if (c.dimids.size() == 1 && c.dimids[0] == var.dimids[i]) names.push_back(c.name);
    }
    const std::string dim = dimension_name(var.grpid, var.dimids[i]);
    // Several 1-D coordinates over a dimension of a rectangular grid (their values
    // monotonic, as cell centres of an unstructured grid never are): which one is the
    // dimension's coordinate is not for the scanner to guess.
    if (names.size() > 1 && std::all_of(names.begin(), names.end(), [&](const std::string& n) {
          return monotonic_in_scope(var.grpid, n);
        })) {
      return make_error(ErrorCode::kInvalidInput,
                        "{}: variable '{}' dimension '{}' has no coordinate variable, and {} 1-D "
                        "variables over it could be one ({}); rename the one that is (e.g. "
                        "ncrename -v {},{})",
                        file_, var.name, dim, names.size(), join(names, ", "), names.front(), dim);
    }
    if (!names.empty() || is_unstructured_dimension_name(dim)) {
      const std::string coordinates =
          names.empty() ? std::string() : ", coordinates " + join(names, " ");
      return make_error(ErrorCode::kUnsupported,
                        "{}: variable '{}' is on an unstructured grid (dimension '{}'{}); {}",
                        file_, var.name, dim, coordinates, kRemapAdvice);
    }
  }
  return std::nullopt;
}

// Horizontal dimensions without coordinate variables whose positions the `coordinates`
// attribute promises in variables the file does not hold (NCL's GRIB conversions name
// 2-D gridlat_N/gridlon_N that may have been left out): a curvilinear grid without its
// coordinates.
std::optional<Error> FileScanner::absent_curvilinear_coordinates_error(
    const VariableDimensions& var, const std::vector<std::string>& absent) {
  std::vector<std::string> bare;
  for (std::size_t i = 0; i < var.dimids.size(); ++i) {
    if (var.coords[i]) continue;
    bare.push_back(fmt::format("'{}'", dimension_name(var.grpid, var.dimids[i])));
  }
  const bool names_lonlat = std::any_of(absent.begin(), absent.end(), [](const std::string& w) {
    const std::string l = lower(w);
    return l.find("lat") != std::string::npos || l.find("lon") != std::string::npos;
  });
  if (bare.size() >= 2 && names_lonlat) {
    return make_error(ErrorCode::kUnsupported,
                      "{}: variable '{}' is on a curvilinear grid: dimensions {} have no "
                      "coordinate variables, and its coordinates attribute names {}, which the "
                      "file does not contain; {}",
                      file_, var.name, join(bare, ", "), join(absent, " "), kCurvilinearAdvice);
  }
  return std::nullopt;
}

// Curvilinear: 2D lon/lat variables over dimensions of this variable that are not
// themselves longitude and latitude.
std::optional<Error> FileScanner::curvilinear_grid_error(
    const VariableDimensions& var, const std::vector<LonLatVariable>& candidates) {
  for (const auto& c : candidates) {
    if (c.dimids.size() < 2) continue;
    bool all_ours = true, any_unresolved = false;
    std::vector<std::string> dim_names;
    for (int d : c.dimids) {
      const auto i = index_of(var.dimids, d);
      if (!i) {
        all_ours = false;
        break;
      }
      any_unresolved = any_unresolved || horizontally_unresolved(var.coords[*i]);
      // Not "'" + s: GCC 12 -O3 warns falsely (PR 105651).
      dim_names.push_back(fmt::format("'{}'", dimension_name(var.grpid, d)));
    }
    if (!all_ours || !any_unresolved) continue;
    std::vector<std::string> names;
    for (const auto& o : candidates) {
      if (o.dimids == c.dimids) names.push_back(o.name);
    }
    return make_error(ErrorCode::kUnsupported,
                      "{}: variable '{}' is on a curvilinear grid (dimensions {}, 2D coordinates "
                      "{}); {}",
                      file_, var.name, join(dim_names, ", "), join(names, " "), kCurvilinearAdvice);
  }
  return std::nullopt;
}

std::optional<Error> FileScanner::detect_unstructured(const VariableDimensions& var) {
  const LonLatCandidates candidates = lonlat_candidates(var.grpid, var.varid);
  if (auto e = unstructured_grid_error(var, candidates.variables)) return e;
  if (auto e = absent_curvilinear_coordinates_error(var, candidates.absent)) return e;
  return curvilinear_grid_error(var, candidates.variables);
}

// Roles from metadata, then the COARDS position for what metadata leaves open.
std::vector<DimensionRole> FileScanner::dimension_roles(const VariableDimensions& var) {
  using R = DimensionRole;
  std::vector<R> roles;
  for (std::size_t i = 0; i < var.dimids.size(); ++i) {
    roles.push_back(
        coordinate(*var.coords[i], is_unlimited_dimension(var.grpid, var.dimids[i])).role);
  }
  const bool has_time_role = std::count(roles.begin(), roles.end(), R::kTime) > 0;
  const std::vector<R> positional = var.dimids.size() == 4 ? std::vector<R>{R::kTime, R::kVertical, R::kLatitude, R::kLongitude}
                                    : has_time_role         ? std::vector<R>{R::kTime, R::kLatitude, R::kLongitude}
                                                            : std::vector<R>{R::kVertical, R::kLatitude, R::kLongitude};
  for (std::size_t i = 0; i < roles.size(); ++i) {
    if (roles[i] != R::kUnknown) continue;
    if (std::count(roles.begin(), roles.end(), positional[i]) == 0) roles[i] = positional[i];
  }
  return roles;
}

// Every role known, none twice, longitude, latitude and vertical present, in
// (time, vertical, lat, lon) order.
std::optional<Rejection> FileScanner::check_dimension_roles(
    const ScannedVariable& sv, const std::vector<DimensionRole>& roles) {
  using R = DimensionRole;
  const std::string dims_text = fmt::format("({})", join(sv.dimensions, ", "));
  std::vector<std::string> role_names;
  for (R r : roles) role_names.emplace_back(dimension_role_name(r));
  const std::string roles_text = fmt::format("({})", join(role_names, ", "));
  for (std::size_t i = 0; i < roles.size(); ++i) {
    if (roles[i] == R::kUnknown) {
      return Rejection{VariableClass::kInvalid,
                       make_error(ErrorCode::kUnsupported,
                                  "{}: variable '{}': cannot tell what dimension '{}' is: its "
                                  "coordinate variable has no axis, standard_name, units or "
                                  "positive attribute that identifies it",
                                  file_, sv.name, sv.dimensions[i])};
    }
  }
  for (R r : {R::kTime, R::kVertical, R::kLatitude, R::kLongitude}) {
    if (std::count(roles.begin(), roles.end(), r) > 1) {
      return Rejection{VariableClass::kInvalid,
                       make_error(ErrorCode::kUnsupported,
                                  "{}: variable '{}' has dimensions {} = {}: more than one {} "
                                  "dimension",
                                  file_, sv.name, dims_text, roles_text, dimension_role_name(r))};
    }
  }
  for (R r : {R::kLongitude, R::kLatitude, R::kVertical}) {
    if (std::count(roles.begin(), roles.end(), r) == 0) {
      return Rejection{VariableClass::kNotGridded,
                       make_error(ErrorCode::kUnsupported,
                                  "{}: variable '{}' has no {} dimension (dimensions {} = {}); {}",
                                  file_, sv.name, dimension_role_name(r), dims_text, roles_text,
                                  k3dOnly)};
    }
  }
  const std::vector<R> expected =
      roles.size() == 4 ? std::vector<R>{R::kTime, R::kVertical, R::kLatitude, R::kLongitude}
                        : std::vector<R>{R::kVertical, R::kLatitude, R::kLongitude};
  if (roles == expected) return std::nullopt;
  std::vector<std::string> reordered;
  for (R want : expected) {
    for (std::size_t i = 0; i < roles.size(); ++i) {
      if (roles[i] == want) reordered.push_back(sv.dimensions[i]);
    }
  }
  return Rejection{VariableClass::kInvalid,
                   make_error(ErrorCode::kUnsupported,
                              "{}: variable '{}' has dimensions {} = {}; the order must be (time, "
                              "vertical, lat, lon) as COARDS/CF recommend — reorder it first, "
                              "e.g. with ncpdq -a {} in.nc out.nc",
                              file_, sv.name, dims_text, roles_text, join(reordered, ","))};
}

Axis FileScanner::coordinate_axis(const VariableRef& ref, AxisKind kind) {
  const Coordinate& c = coordinate(ref, false);
  // Pressures known exactly per level: a pressure axis, no geometry field.
  if (kind == AxisKind::kOther && c.attrs.has_formula_terms &&
      lower(c.attrs.standard_name) == kLnPressureCoordinate) {
    return read_ln_pressure_axis(ref.grpid, ref.varid, file_);
  }
  Axis a;
  a.name = c.attrs.name;
  a.kind = kind == AxisKind::kOther ? detect_vertical_kind(c.attrs) : kind;
  a.units = c.attrs.units;
  a.standard_name = c.attrs.standard_name;
  a.long_name = c.attrs.long_name;
  a.positive = lower(c.attrs.positive);
  a.values = c.values;
  return a;
}

// The axes of a variable whose dimensions are (time,) vertical, lat, lon; throws Error
// when they do not make a grid.
TimeCoordinate FileScanner::time_coordinate(const VariableDimensions& var) {
  const Coordinate& c = coordinate(*var.coords[0], false);
  TimeCoordinate t{c.attrs.name, c.attrs.units, c.calendar, c.values};
  Axis as_axis;
  as_axis.name = t.name;
  as_axis.values = t.values;
  check_axis_values(as_axis, file_);
  return t;
}

void FileScanner::read_axes(ScannedVariable& sv, const VariableDimensions& var) {
  const std::size_t first_spatial = var.dimids.size() - 3;
  sv.z = coordinate_axis(*var.coords[first_spatial], AxisKind::kOther);
  sv.y = coordinate_axis(*var.coords[first_spatial + 1], AxisKind::kLatitude);
  sv.x = coordinate_axis(*var.coords[first_spatial + 2], AxisKind::kLongitude);
  const std::string what = fmt::format("{}: variable '{}'", file_, sv.name);
  // Longitude and latitude, or projection coordinates placed by a grid mapping; a
  // wrapped longitude axis is made continuous, one round the Earth periodic.
  HorizontalAxes horizontal =
      place_horizontal_axes(sv.x, sv.y, read_grid_mapping(var.grpid, var.varid, what), what);
  for (std::string& note : horizontal.notes) {
    // Once per file and axis, not once per variable: named by the file alone.
    if (note.compare(0, what.size(), what) == 0) note.replace(0, what.size(), file_);
    if (logged_.insert(note).second) spdlog::info("{}", note);
  }
  sv.grid_mapping = std::move(horizontal.mapping);
  sv.source_nx = horizontal.source_nx;
  for (const Axis* a : {&sv.x, &sv.y, &sv.z}) check_axis_values(*a, file_);
  if (var.dimids.size() == 4) sv.time = time_coordinate(var);
}

// A (time?, vertical?, y, x) variable whose y and x dimensions have no coordinate variables
// and whose `coordinates` attribute names exactly one longitude and one latitude (units
// degrees_east / degrees_north or standard_name longitude / latitude) over exactly
// (y, x). None when a name it gives that could be one of them is not in the file: that
// variable is refused (absent_curvilinear_coordinates_error).
std::optional<CurvilinearCoordinates> FileScanner::curvilinear_coordinates(
    const VariableDimensions& var) {
  const std::size_t n = var.dimids.size();
  if (n < 2 || n > 4 || var.coords[n - 2] || var.coords[n - 1]) return std::nullopt;
  const std::vector<int> horizontal{var.dimids[n - 2], var.dimids[n - 1]};
  std::vector<CurvilinearCoordinates> lons, lats;
  for (const std::string& word :
       split_words(text_attribute_or_empty(var.grpid, var.varid, "coordinates"))) {
    std::optional<VariableRef> ref;
    for (std::optional<int> g = var.grpid; g && !ref; g = parent_group(*g)) {
      int varid = -1;
      if (nc_inq_varid(*g, word.c_str(), &varid) == NC_NOERR) ref = VariableRef{*g, varid};
    }
    if (!ref) {
      const std::string l = lower(word);
      if (l.find("lat") != std::string::npos || l.find("lon") != std::string::npos) {
        return std::nullopt;
      }
      continue;
    }
    if (variable_dimids(ref->grpid, ref->varid) != horizontal ||
        !is_numeric_type(variable_type(ref->grpid, ref->varid))) {
      continue;
    }
    const CoordinateAttributes attrs = read_coordinate_attributes(ref->grpid, ref->varid);
    if (looks_like_longitude(attrs)) lons.push_back({*ref, {}, word, {}});
    if (looks_like_latitude(attrs)) lats.push_back({{}, *ref, {}, word});
  }
  if (lons.size() != 1 || lats.size() != 1 || lons[0].lon_name == lats[0].lat_name) {
    return std::nullopt;
  }
  return CurvilinearCoordinates{lons[0].lon, lats[0].lat, lons[0].lon_name, lats[0].lat_name};
}

// The checked grid of 2-D coordinates `c`, read once per file.
std::shared_ptr<const CurvilinearGrid> FileScanner::curvilinear_grid(
    const CurvilinearCoordinates& c, std::size_t nx, std::size_t ny, const std::string& what) {
  const auto key = std::make_tuple(c.lon.grpid, c.lon.varid, c.lat.grpid, c.lat.varid);
  if (auto it = curvilinear_.find(key); it != curvilinear_.end()) return it->second;
  auto missing_values = [](const VariableRef& ref) {
    std::vector<double> out;
    for (const char* attr : {"_FillValue", "missing_value"}) {
      for (long double v : numeric_attribute(ref.grpid, ref.varid, attr)) {
        out.push_back(static_cast<double>(v));
      }
    }
    return out;
  };
  auto grid = std::make_shared<const CurvilinearGrid>(make_curvilinear_grid(
      c.lon_name, c.lat_name, nx, ny,
      read_all_as_double(c.lon.grpid, c.lon.varid,
                         fmt::format("{}: 2-D coordinate '{}'", file_, c.lon_name)),
      read_all_as_double(c.lat.grpid, c.lat.varid,
                         fmt::format("{}: 2-D coordinate '{}'", file_, c.lat_name)),
      missing_values(c.lon), missing_values(c.lat), what));
  return curvilinear_.emplace(key, std::move(grid)).first->second;
}

// A variable on a curvilinear grid: index axes x and y, its vertical and time axes from
// their coordinate variables, its columns placed by the 2-D coordinates.
ScannedVariable FileScanner::scan_curvilinear(ScannedVariable sv, const VariableDimensions& var,
                                              const CurvilinearCoordinates& coordinates) {
  auto fail = [&](VariableClass klass, Error error) {
    sv.klass = klass;
    sv.problem = std::move(error);
    return std::move(sv);
  };
  using R = DimensionRole;
  const std::size_t n = var.dimids.size();
  std::vector<R> roles;
  for (std::size_t i = 0; i + 2 < n; ++i) {
    if (!var.coords[i]) {
      return fail(VariableClass::kInvalid,
                  make_error(ErrorCode::kInvalidInput,
                             "{}: variable '{}' dimension '{}' has no coordinate variable", file_,
                             sv.name, sv.dimensions[i]));
    }
    roles.push_back(
        coordinate(*var.coords[i], is_unlimited_dimension(var.grpid, var.dimids[i])).role);
  }
  const std::vector<R> positional =
      n == 4 ? std::vector<R>{R::kTime, R::kVertical} : std::vector<R>{R::kVertical};
  for (std::size_t i = 0; i < roles.size(); ++i) {
    if (roles[i] == R::kUnknown && std::count(roles.begin(), roles.end(), positional[i]) == 0) {
      roles[i] = positional[i];
    }
  }
  roles.push_back(R::kLatitude);
  roles.push_back(R::kLongitude);
  if (auto r = check_dimension_roles(sv, roles)) return fail(r->klass, std::move(r->error));

  const std::string what = fmt::format("{}: variable '{}'", file_, sv.name);
  try {
    const std::size_t nx = dimension_length(var.grpid, var.dimids[n - 1]);
    const std::size_t ny = dimension_length(var.grpid, var.dimids[n - 2]);
    sv.curvilinear = curvilinear_grid(coordinates, nx, ny, what);
    for (auto [axis, size, dim] : {std::tuple{&sv.x, nx, n - 1}, std::tuple{&sv.y, ny, n - 2}}) {
      axis->name = sv.dimensions[dim];
      axis->kind = AxisKind::kIndex;
      axis->values.resize(size);
      for (std::size_t k = 0; k < size; ++k) axis->values[k] = static_cast<double>(k);
    }
    sv.source_nx = nx;
    sv.z = coordinate_axis(*var.coords[n - 3], AxisKind::kOther);
    for (const Axis* a : {&sv.x, &sv.y, &sv.z}) check_axis_values(*a, file_);
    if (n == 4) sv.time = time_coordinate(var);
  } catch (const Error& e) {
    return fail(VariableClass::kInvalid, e);
  }
  if (has_attribute(var.grpid, var.varid, "grid_mapping")) {
    const std::string note = fmt::format(
        "{}: grid_mapping '{}' is not used: dimensions '{}' and '{}' have no 1-D projection "
        "coordinates; the 2-D '{}' and '{}' place the grid",
        file_, text_attribute_or_empty(var.grpid, var.varid, "grid_mapping"), sv.dimensions[n - 1],
        sv.dimensions[n - 2], coordinates.lon_name, coordinates.lat_name);
    if (logged_.insert(note).second) spdlog::info("{}", note);
  }
  sv.meta = read_variable_meta(var.grpid, var.varid, sv.name);
  sv.value_attributes = read_value_attributes(var.grpid, var.varid);
  sv.klass = VariableClass::kGrid3D;
  return sv;
}

ScannedVariable FileScanner::scan_variable(int grpid, int varid, const std::string& prefix) {
  ScannedVariable sv;
  const std::string short_name = variable_name(grpid, varid);
  sv.name = prefix + short_name;
  const int type = variable_type(grpid, varid);
  VariableDimensions var{grpid, varid, sv.name, variable_dimids(grpid, varid), {}};
  for (int d : var.dimids) sv.dimensions.push_back(dimension_name(grpid, d));
  const bool is_coordinate = var.dimids.size() == 1 && sv.dimensions[0] == short_name;
  sv.auxiliary = is_coordinate || auxiliary_.count(short_name) > 0;

  auto fail = [&](VariableClass klass, Error error) {
    sv.klass = klass;
    sv.problem = std::move(error);
    return std::move(sv);
  };
  if (is_coordinate) {
    return fail(VariableClass::kNotGridded,
                make_error(ErrorCode::kUnsupported,
                           "{}: '{}' is a coordinate variable, not a data variable", file_,
                           sv.name));
  }
  if (!is_numeric_type(type)) {
    return fail(VariableClass::kNotGridded,
                make_error(ErrorCode::kUnsupported,
                           "{}: variable '{}' has type {}; only numeric variables can be converted",
                           file_, sv.name, nc_type_name(type)));
  }

  std::vector<std::string> missing;
  for (std::size_t i = 0; i < var.dimids.size(); ++i) {
    var.coords.push_back(find_coordinate_variable(grpid, var.dimids[i]));
    if (!var.coords.back()) var.coords.back() = paired_coordinate(grpid, var.dimids[i]);
    if (!var.coords.back()) missing.push_back(sv.dimensions[i]);
  }
  if (auto c = curvilinear_coordinates(var)) {
    if (var.dimids.size() >= 3) return scan_curvilinear(std::move(sv), var, *c);
    // A 2-D field on the grid (a surface height): not a 3-D variable, and no grid problem.
    return fail(VariableClass::kNotGridded,
                make_error(ErrorCode::kUnsupported, "{}: variable '{}' has dimensions ({}); {}",
                           file_, sv.name, join(sv.dimensions, ", "), k3dOnly));
  }
  if (auto e = detect_unstructured(var)) return fail(VariableClass::kUnstructured, std::move(*e));
  if (!missing.empty()) {
    return fail(var.dimids.size() >= 3 ? VariableClass::kInvalid : VariableClass::kNotGridded,
                make_error(ErrorCode::kInvalidInput,
                           "{}: variable '{}' dimension '{}' has no coordinate variable", file_,
                           sv.name, missing.front()));
  }
  if (var.dimids.size() < 3 || var.dimids.size() > 4) {
    return fail(VariableClass::kNotGridded,
                make_error(ErrorCode::kUnsupported, "{}: variable '{}' has dimensions ({}); {}",
                           file_, sv.name, join(sv.dimensions, ", "), k3dOnly));
  }
  if (auto r = check_dimension_roles(sv, dimension_roles(var))) {
    return fail(r->klass, std::move(r->error));
  }
  try {
    read_axes(sv, var);
  } catch (const Error& e) {
    return fail(VariableClass::kInvalid, e);
  }
  sv.meta = read_variable_meta(grpid, varid, sv.name);
  sv.value_attributes = read_value_attributes(grpid, varid);
  sv.klass = VariableClass::kGrid3D;
  return sv;
}

}  // namespace

ScannedFile scan_file(const std::filesystem::path& path) {
  ScannedFile out;
  out.source = describe_source_file(path);
  const std::string& display = out.source.path;
  try {
    std::lock_guard lock(netcdf_mutex());
    NcFile file{std::filesystem::path(display)};
    out.format = file.format();
    // WRF output: its 2-D XLAT/XLONG lie on a map projection its attributes describe.
    if (is_wrf_file(file.id())) {
      out.variables = scan_wrf_variables(file.id(), display);
    } else {
      FileScanner scanner(display, file.id());
      out.variables = scanner.scan_all();
    }
  } catch (const Error& e) {
    if (std::string_view(e.what()).substr(0, display.size()) == display) throw;
    throw e.with_context(display);
  }
  return out;
}

}  // namespace strielad::ingest
