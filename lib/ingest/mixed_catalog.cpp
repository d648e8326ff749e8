// SPDX-License-Identifier: Apache-2.0
#include "ingest/mixed_catalog.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include "core/error.h"
#include "ingest/grid_compare.h"
#include "ingest/requested_steps.h"
#include "ingest/time_reconciliation.h"

namespace strielad::ingest {
namespace {

// 1582-10-15 00:00:00 in seconds since 1970-01-01: from then on the standard (mixed
// Julian/Gregorian) calendar and the proleptic Gregorian one name the same days.
constexpr double kFirstGregorianSecond = -12219292800.0;

// One side of the join: its catalog and how messages name it.
struct Side {
  const InputCatalog& catalog;
  std::string_view kind;  // "GRIB" or "netCDF"

  // The file of the side's first variable at its first step, for messages.
  const std::string& file() const {
    const auto& loc = catalog.locations;
    return !loc.empty() && !loc.front().empty() ? catalog.files[loc.front().front().file].path
                                                : catalog.files.front().path;
  }
  std::string where() const {
    return fmt::format("{} input {} (variable '{}')", kind, file(), catalog.variables.front().name);
  }
};

std::string lowercase(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool standard_calendar(std::string_view calendar) {
  const std::string c = lowercase(calendar);
  return c.empty() || c == "standard" || c == "gregorian";
}

void refuse_vertical_geometry(const Side& s, const Side& other) {
  const InputCatalog& c = s.catalog;
  if (!c.vertical_geometry && !c.surface && c.grib_fields.empty()) return;
  const std::string what =
      c.vertical_geometry
          ? fmt::format("levels placed by a vertical geometry ({} from {})",
                        c.vertical_geometry->formula, fmt::join(c.vertical_geometry->sources, ", "))
          : fmt::format("a surface height field ('{}')",
                        c.surface ? c.surface->variable : c.grib_fields.begin()->first);
  throw make_error(ErrorCode::kUnsupported,
                   "{}: the {} variables are on {} axis '{}' with {}; GRIB and netCDF inputs are "
                   "mixed only on levels the z axis places alone (pressure, height), so {} cannot "
                   "join them: convert each format separately",
                   s.file(), s.kind, axis_kind_name(c.z.kind), c.z.name, what, other.file());
}

void refuse_curvilinear(const Side& s, const Side& other) {
  if (!s.catalog.curvilinear) return;
  throw make_error(ErrorCode::kUnsupported,
                   "{}: the {} variables are on a curvilinear grid (2-D '{}' and '{}'), {} is not; "
                   "GRIB and netCDF inputs are mixed only on one rectilinear or projected grid",
                   s.file(), s.kind, s.catalog.curvilinear->lon_variable,
                   s.catalog.curvilinear->lat_variable, other.where());
}

// Kind, units and every value; the coordinate variables' names may differ.
std::optional<std::string> axis_mismatch(const Axis& got, const Axis& want,
                                         std::string_view want_where) {
  if (got.kind != want.kind) {
    return fmt::format("axis '{}' is a {} axis but axis '{}' of {} is a {} axis", got.name,
                       axis_kind_name(got.kind), want.name, want_where, axis_kind_name(want.kind));
  }
  Axis renamed = got;
  renamed.name = want.name;
  const auto d = axis_difference(renamed, want, want_where);
  if (!d || got.name == want.name) return d;
  return fmt::format("axis '{}' (axis '{}' there): {}", got.name, want.name, *d);
}

void check_same_grid(const Side& got, const Side& want) {
  const InputCatalog& a = got.catalog;
  const InputCatalog& b = want.catalog;
  const std::string where = want.where();
  std::optional<std::string> d = axis_mismatch(a.x, b.x, where);
  if (!d) d = axis_mismatch(a.y, b.y, where);
  if (!d) d = axis_mismatch(a.z, b.z, where);
  if (!d && a.x.periodic != b.x.periodic) {
    d = fmt::format("axis '{}' {} round the Earth but {} {}", a.x.name,
                    a.x.periodic ? "goes" : "does not go", where, b.x.periodic ? "does" : "does not");
  }
  if (d) {
    throw make_error(ErrorCode::kInvalidInput, "{}: the {} variables are not on the grid of {}: {}",
                     got.file(), got.kind, where, *d);
  }
  const auto describe = [](const std::optional<GridMapping>& m) {
    return m ? fmt::format("grid mapping '{}' ({}, PROJ '{}')", m->variable, m->name, m->proj)
             : std::string("no grid mapping");
  };
  const auto& ma = a.grid_mapping;
  const auto& mb = b.grid_mapping;
  const bool same = ma.has_value() == mb.has_value() &&
                    (!ma || (ma->name == mb->name && ma->proj == mb->proj));
  if (!same) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: the {} variables have {} but {} has {}; GRIB and netCDF inputs must be "
                     "placed by the same projection",
                     got.file(), got.kind, describe(ma), where, describe(mb));
  }
}

void check_distinct_variables(const Side& a, const Side& b) {
  for (const auto& v : a.catalog.variables) {
    for (std::size_t w = 0; w < b.catalog.variables.size(); ++w) {
      if (b.catalog.variables[w].name != v.name) continue;
      throw make_error(ErrorCode::kInvalidInput,
                       "variable '{}' is in {} input {} and in {} input {}: every variable of a "
                       "conversion comes from one format; choose with --vars or leave one out",
                       v.name, a.kind, a.file(), b.kind, b.catalog.files[b.catalog.locations[w]
                                                                              .front()
                                                                              .file]
                                                             .path);
    }
  }
}

TimeCoordinate time_coordinate(const InputCatalog& c) {
  return TimeCoordinate{c.time.name, c.time.units, c.time.calendar, c.time.values};
}

// The GRIB side's time coordinate in the netCDF side's calendar where they name the same
// days: GRIB validity times are proleptic Gregorian; from 1582-10-15 on, the standard
// calendar agrees with it.
TimeCoordinate grib_time_in_calendar_of(const Side& grib, const Side& netcdf) {
  TimeCoordinate t = time_coordinate(grib.catalog);
  if (!standard_calendar(netcdf.catalog.time.calendar)) return t;
  const auto earliest = std::min_element(t.values.begin(), t.values.end());
  if (earliest != t.values.end() && *earliest < kFirstGregorianSecond) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: GRIB validity time {} s since 1970 is before 1582-10-15, where the "
                     "calendar '{}' of {} is Julian and GRIB's proleptic Gregorian",
                     grib.file(), *earliest, netcdf.catalog.time.calendar, netcdf.where());
  }
  t.calendar = netcdf.catalog.time.calendar;
  return t;
}

std::string step_text(double value, const std::string& units) {
  return units.empty() ? fmt::format("{}", value) : fmt::format("{} ({})", value, units);
}

// The other side's steps in the reference's units, which must be the reference's steps.
void check_same_steps(const Side& ref, const TimeCoordinate& ref_time, const Side& other,
                      const TimeCoordinate& other_time) {
  const TimeUnitsReconciler reconciler(ref_time, ref.where());
  const std::vector<double> mine = reconciler.values(ref_time, ref.where());
  const std::vector<double> theirs = reconciler.values(other_time, other.where());
  const std::string& units = reconciler.units();
  for (const double t : mine) {
    if (std::find(theirs.begin(), theirs.end(), t) != theirs.end()) continue;
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: the {} variables have no time step {}, which {} has; GRIB and netCDF "
                     "inputs must have the same time steps",
                     other.file(), other.kind, step_text(t, units), ref.where());
  }
  for (const double t : theirs) {
    if (std::find(mine.begin(), mine.end(), t) != mine.end()) continue;
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: the {} variables have no time step {}, which {} has; GRIB and netCDF "
                     "inputs must have the same time steps",
                     ref.file(), ref.kind, step_text(t, units), other.where());
  }
  if (mine.size() != theirs.size()) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: the {} variables have {} time steps, {} has {}; GRIB and netCDF inputs "
                     "must have the same time steps",
                     other.file(), other.kind, theirs.size(), ref.where(), mine.size());
  }
}

}  // namespace

InputCatalog merge_grib_and_netcdf(const InputCatalog& grib, const InputCatalog& netcdf,
                                   bool grib_first, const ScanOptions& options) {
  const Side g{grib, "GRIB"};
  const Side n{netcdf, "netCDF"};
  const Side& ref = grib_first ? g : n;
  const Side& other = grib_first ? n : g;

  refuse_vertical_geometry(g, n);
  refuse_vertical_geometry(n, g);
  refuse_curvilinear(n, g);
  check_same_grid(other, ref);
  check_distinct_variables(ref, other);

  if (netcdf.time.name.empty() && netcdf.time.units.empty()) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: the netCDF variables have no time dimension but {} has validity times; "
                     "mixed with GRIB, netCDF inputs need a time coordinate",
                     n.file(), g.where());
  }
  const TimeCoordinate grib_time = grib_time_in_calendar_of(g, n);
  const TimeCoordinate netcdf_time = time_coordinate(netcdf);
  check_same_steps(ref, grib_first ? grib_time : netcdf_time, other,
                   grib_first ? netcdf_time : grib_time);

  // The reference's units and calendar (GRIB's proleptic Gregorian stays so: the steps
  // are from 1582-10-15 on, where it is the standard calendar).
  InputCatalog c = ref.catalog;
  const std::size_t file_offset = c.files.size();
  c.files.insert(c.files.end(), other.catalog.files.begin(), other.catalog.files.end());
  // Both sides' steps ascend and are the same instants: step i is step i.
  for (std::size_t v = 0; v < other.catalog.variables.size(); ++v) {
    c.variables.push_back(other.catalog.variables[v]);
    auto locations = other.catalog.locations[v];
    for (auto& loc : locations) loc.file += file_offset;
    c.locations.push_back(std::move(locations));
  }

  const std::size_t steps = c.time.size();
  const StepRange range = requested_steps(options, steps);
  const auto first = static_cast<std::ptrdiff_t>(range.first);
  const auto end = static_cast<std::ptrdiff_t>(range.last) + 1;
  c.time.values = std::vector<double>(c.time.values.begin() + first, c.time.values.begin() + end);
  for (auto& per_step : c.locations) {
    per_step = std::vector<VariableLocation>(per_step.begin() + first, per_step.begin() + end);
  }

  std::vector<std::string> names;
  for (const auto& v : c.variables) names.push_back(v.name);
  spdlog::info("GRIB and netCDF inputs joined: {} GRIB and {} netCDF file{}, {} variable{} ({}) "
               "on a {} x {} x {} grid, {} of {} time step{}",
               grib.files.size(), netcdf.files.size(), netcdf.files.size() == 1 ? "" : "s",
               names.size(), names.size() == 1 ? "" : "s", fmt::join(names, ", "), c.x.size(),
               c.y.size(), c.z.size(), c.time.size(), steps, steps == 1 ? "" : "s");
  return c;
}

}  // namespace strielad::ingest
