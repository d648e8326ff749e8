// SPDX-License-Identifier: Apache-2.0
// scan_inputs: scans every file, selects the variables, and merges the files into one
// catalog: one grid (identical in every file), one time axis (sorted, every variable at
// every step found in exactly one file), and consistent CF attributes per variable. GRIB
// inputs make their own catalog (grib_catalog.h); GRIB and netCDF inputs together make
// one of each, joined by mixed_catalog.h.
#include "ingest/input_catalog.h"

#include "ingest/grib_catalog.h"
#include "ingest/input_kind.h"
#include "ingest/mixed_catalog.h"
#include "ingest/requested_steps.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include "core/error.h"
#include "ingest/file_scan.h"
#include "ingest/grid_compare.h"
#include "ingest/netcdf_file.h"
#include "ingest/variable_selection.h"
#include "ingest/time_reconciliation.h"
#include "ingest/vertical_geometry_detection.h"

namespace strielad::ingest {
namespace {

struct Occurrence {
  std::size_t file = 0;
  const ScannedVariable* variable = nullptr;
};

std::string describe_time_units(const ScannedVariable& v) {
  if (!v.time) return "no time dimension";
  return fmt::format("time units '{}' (calendar '{}')", v.time->units, v.time->calendar);
}

// A time value in the catalog's units (`reconciler`; none: files without time).
std::string time_text(double value, const std::optional<TimeUnitsReconciler>& reconciler) {
  if (!reconciler) return "(the single step of a file without time dimension)";
  return reconciler->units().empty() ? fmt::format("{}", value)
                                     : fmt::format("{} ({})", value, reconciler->units());
}

template <typename T>
std::string optional_text(const std::optional<T>& v) {
  return v ? fmt::format("{}", static_cast<double>(*v)) : std::string("none");
}

// Attributes that decide how raw samples become values must agree across files.
void check_same_attributes(const ScannedVariable& got, const std::string& got_file,
                           const ScannedVariable& want, const std::string& want_file) {
  auto mismatch = [&](std::string_view what, const std::string& g, const std::string& w) {
    return make_error(ErrorCode::kInvalidInput, "{}: variable '{}' has {} {} but {} has {}",
                      got_file, got.name, what, g, want_file, w);
  };
  const CfValueAttributes& a = got.value_attributes;
  const CfValueAttributes& b = want.value_attributes;
  if (got.meta.source_type != want.meta.source_type) {
    throw mismatch("type", got.meta.source_type, want.meta.source_type);
  }
  if (a.scale_factor != b.scale_factor) {
    throw mismatch("scale_factor", optional_text(a.scale_factor), optional_text(b.scale_factor));
  }
  if (a.add_offset != b.add_offset) {
    throw mismatch("add_offset", optional_text(a.add_offset), optional_text(b.add_offset));
  }
  if (got.meta.store_type != want.meta.store_type) {
    throw mismatch("packing attribute type", std::string(dtype_name(got.meta.store_type)),
                   std::string(dtype_name(want.meta.store_type)));
  }
  // NaN fill values compare unequal to themselves: compare their text.
  if (optional_text(a.fill_value) != optional_text(b.fill_value)) {
    throw mismatch("_FillValue", optional_text(a.fill_value), optional_text(b.fill_value));
  }
  auto list_text = [](const std::vector<long double>& v) {
    std::vector<double> d(v.begin(), v.end());
    return d.empty() ? std::string("none") : fmt::format("{}", fmt::join(d, " "));
  };
  if (list_text(a.missing_values) != list_text(b.missing_values)) {
    throw mismatch("missing_value", list_text(a.missing_values), list_text(b.missing_values));
  }
  if (a.valid_min != b.valid_min) {
    throw mismatch("valid_min", optional_text(a.valid_min), optional_text(b.valid_min));
  }
  if (a.valid_max != b.valid_max) {
    throw mismatch("valid_max", optional_text(a.valid_max), optional_text(b.valid_max));
  }
  if (got.meta.units != want.meta.units) {
    throw mismatch("units", "'" + got.meta.units + "'", "'" + want.meta.units + "'");
  }
}

// The scanned files with every occurrence of each selected variable.
struct SelectedInputs {
  std::vector<ScannedFile> files;
  std::vector<std::string> names;
  std::vector<std::vector<Occurrence>> occurrences;  // per name, in file order

  const std::string& path(std::size_t f) const { return files[f].source.path; }
  const Occurrence& reference() const { return occurrences[0][0]; }
};

std::vector<ScannedFile> scan_distinct_files(const std::vector<std::filesystem::path>& inputs) {
  std::vector<ScannedFile> files;
  std::map<std::string, std::size_t> seen_paths;
  for (const auto& path : inputs) {
    files.push_back(scan_file(path));
    const std::string& p = files.back().source.path;
    if (!seen_paths.emplace(p, files.size() - 1).second) {
      throw make_error(ErrorCode::kInvalidArgument, "{}: input file given twice", p);
    }
  }
  return files;
}

// Every occurrence of a selected variable must be usable.
std::vector<std::vector<Occurrence>> usable_occurrences(const std::vector<ScannedFile>& files,
                                                        const std::vector<std::string>& names) {
  std::vector<std::vector<Occurrence>> occurrences(names.size());
  for (std::size_t v = 0; v < names.size(); ++v) {
    for (std::size_t f = 0; f < files.size(); ++f) {
      const ScannedVariable* sv = files[f].find(names[v]);
      if (sv == nullptr) continue;
      if (sv->klass != VariableClass::kGrid3D) throw *sv->problem;
      occurrences[v].push_back({f, sv});
    }
  }
  return occurrences;
}

// One grid: each variable matches itself across files, and the first variable.
void check_one_grid(const SelectedInputs& in) {
  const Occurrence& reference = in.reference();
  for (std::size_t v = 0; v < in.names.size(); ++v) {
    const Occurrence& first = in.occurrences[v][0];
    if (v > 0) {
      const auto& r = *reference.variable;
      if (auto d = grid_difference(first.variable->x, first.variable->y, first.variable->z, r.x,
                                   r.y, r.z, fmt::format("variable '{}'", r.name))) {
        throw make_error(ErrorCode::kInvalidInput,
                         "{}: variable '{}' is not on the grid of variable '{}' ({}): {}",
                         in.path(first.file), in.names[v], r.name, in.path(reference.file), *d);
      }
    }
    for (std::size_t o = 1; o < in.occurrences[v].size(); ++o) {
      const Occurrence& occ = in.occurrences[v][o];
      const auto& a = *occ.variable;
      const auto& b = *first.variable;
      if (auto d = grid_difference(a.x, a.y, a.z, b.x, b.y, b.z, in.path(first.file))) {
        throw make_error(ErrorCode::kInvalidInput, "{}: {} (variable '{}')", in.path(occ.file), *d,
                         in.names[v]);
      }
      check_same_attributes(a, in.path(occ.file), b, in.path(first.file));
    }
  }
}

// One placement: the same grid mapping (or none) for every variable in every file.
void check_one_grid_mapping(const SelectedInputs& in) {
  const Occurrence& reference = in.reference();
  for (std::size_t v = 0; v < in.names.size(); ++v) {
    for (const Occurrence& occ : in.occurrences[v]) {
      const ScannedVariable& a = *occ.variable;
      const ScannedVariable& r = *reference.variable;
      if (a.grid_mapping == r.grid_mapping) continue;
      auto describe = [](const ScannedVariable& x) {
        return x.grid_mapping ? fmt::format("grid mapping '{}' ({})", x.grid_mapping->variable,
                                            x.grid_mapping->name)
                              : std::string("no grid mapping");
      };
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: variable '{}' has {} but variable '{}' in {} has {}{}",
                       in.path(occ.file), a.name, describe(a), r.name, in.path(reference.file),
                       describe(r),
                       a.grid_mapping && r.grid_mapping ? " (their attributes differ)" : "");
    }
  }
}

// One curvilinear grid (or none): the same 2-D coordinates for every variable in every
// file, value for value.
void check_one_curvilinear_grid(const SelectedInputs& in) {
  const Occurrence& reference = in.reference();
  const ScannedVariable& r = *reference.variable;
  for (std::size_t v = 0; v < in.names.size(); ++v) {
    for (const Occurrence& occ : in.occurrences[v]) {
      const ScannedVariable& a = *occ.variable;
      if (a.curvilinear == r.curvilinear) continue;
      const std::string where = fmt::format("variable '{}' in {}", r.name, in.path(reference.file));
      if (!a.curvilinear || !r.curvilinear) {
        throw make_error(ErrorCode::kInvalidInput,
                         "{}: variable '{}' is {} but {} is {}", in.path(occ.file), a.name,
                         a.curvilinear ? "on a curvilinear grid" : "not on a curvilinear grid",
                         where, r.curvilinear ? "on one" : "not");
      }
      if (auto d = curvilinear_difference(*a.curvilinear, *r.curvilinear, where)) {
        throw make_error(ErrorCode::kInvalidInput, "{}: variable '{}': {}", in.path(occ.file),
                         a.name, *d);
      }
    }
  }
}

// The first occurrence in file order: its time units and calendar are the reference.
const Occurrence& time_reference(const SelectedInputs& in) {
  for (std::size_t f = 0; f < in.files.size(); ++f) {
    for (std::size_t v = 0; v < in.names.size(); ++v) {
      for (const auto& occ : in.occurrences[v]) {
        if (occ.file == f) return occ;
      }
    }
  }
  return in.reference();
}

// Where each (variable, time) is: every time in the reference's units (`reconciler`),
// each step in exactly one file.
std::vector<std::map<double, VariableLocation>> locate_time_steps(
    const SelectedInputs& in, const Occurrence& tref_occ,
    const std::optional<TimeUnitsReconciler>& reconciler) {
  const ScannedVariable& tref = *tref_occ.variable;
  std::vector<std::map<double, VariableLocation>> steps(in.names.size());
  for (std::size_t v = 0; v < in.names.size(); ++v) {
    for (const Occurrence& occ : in.occurrences[v]) {
      const ScannedVariable& sv = *occ.variable;
      if (sv.time.has_value() != tref.time.has_value()) {
        throw make_error(ErrorCode::kInvalidInput,
                         "{}: variable '{}' has {} but {} has {} (variable '{}'); all inputs must "
                         "have a time dimension, or none",
                         in.path(occ.file), sv.name, describe_time_units(sv),
                         in.path(tref_occ.file), describe_time_units(tref), tref.name);
      }
      const std::vector<double> values =
          sv.time ? reconciler->values(*sv.time, fmt::format("{}: variable '{}'",
                                                             in.path(occ.file), sv.name))
                  : std::vector<double>{0.0};
      for (std::size_t i = 0; i < values.size(); ++i) {
        auto [it, inserted] = steps[v].emplace(values[i], VariableLocation{occ.file, i, {}});
        if (inserted) continue;
        if (!sv.time) {
          throw make_error(ErrorCode::kInvalidInput,
                           "variable '{}' has no time dimension in both {} and {}: files without "
                           "a time dimension can hold only one step of a variable",
                           sv.name, in.path(it->second.file), in.path(occ.file));
        }
        throw make_error(ErrorCode::kInvalidInput,
                         "variable '{}' time {} is in both {} and {} (duplicate time step)",
                         sv.name, time_text(values[i], reconciler), in.path(it->second.file),
                         in.path(occ.file));
      }
    }
  }
  return steps;
}

// The union of all time steps, each of which every variable must have.
std::vector<double> common_time_steps(const SelectedInputs& in,
                                      const std::vector<std::map<double, VariableLocation>>& steps,
                                      const std::optional<TimeUnitsReconciler>& reconciler) {
  std::set<double> all_times;
  for (const auto& s : steps) {
    for (const auto& [t, loc] : s) all_times.insert(t);
  }
  for (std::size_t v = 0; v < in.names.size(); ++v) {
    if (steps[v].size() == all_times.size()) continue;
    for (double t : all_times) {
      if (steps[v].count(t)) continue;
      for (std::size_t w = 0; w < in.names.size(); ++w) {
        auto it = steps[w].find(t);
        if (it == steps[w].end()) continue;
        throw make_error(ErrorCode::kInvalidInput,
                         "variable '{}' has no time step {}, which {} has for variable '{}'; "
                         "every variable must have the same time steps",
                         in.names[v], time_text(t, reconciler), in.path(it->second.file),
                         in.names[w]);
      }
    }
  }
  return std::vector<double>(all_times.begin(), all_times.end());
}

// The inputs by format, each in input order. Files that do not exist are left to the
// netCDF scan, which names them.
struct InputsByFormat {
  std::vector<std::filesystem::path> grib, netcdf;
  bool grib_first = false;
};

InputsByFormat inputs_by_format(const std::vector<std::filesystem::path>& inputs) {
  InputsByFormat k;
  for (const auto& path : inputs) {
    std::error_code ec;
    const bool grib = std::filesystem::is_regular_file(path, ec) &&
                      detect_input_kind(path).kind == InputKind::kGrib;
    if (k.grib.empty() && k.netcdf.empty()) k.grib_first = grib;
    (grib ? k.grib : k.netcdf).push_back(path);
  }
  return k;
}

// The grid, placement and variable descriptions, all taken from the reference variable.
InputCatalog catalog_without_time(const SelectedInputs& in) {
  const ScannedVariable& r = *in.reference().variable;
  InputCatalog catalog;
  for (const auto& f : in.files) catalog.files.push_back(f.source);
  catalog.x = r.x;
  catalog.y = r.y;
  catalog.z = r.z;
  catalog.grid_mapping = r.grid_mapping;
  catalog.curvilinear = r.curvilinear;
  catalog.source_nx = r.source_nx;
  for (std::size_t v = 0; v < in.names.size(); ++v) {
    catalog.variables.push_back(in.occurrences[v][0].variable->meta);
  }
  return catalog;
}

// The catalog of netCDF inputs, scanned (scan_distinct_files).
InputCatalog netcdf_catalog(std::vector<ScannedFile> files, const ScanOptions& options) {
  SelectedInputs in;
  in.files = std::move(files);
  in.names = select_variables(in.files, options.variables, height_field_names(options));
  in.occurrences = usable_occurrences(in.files, in.names);
  check_one_grid(in);
  check_one_grid_mapping(in);
  check_one_curvilinear_grid(in);
  InputCatalog catalog = catalog_without_time(in);

  const Occurrence& tref_occ = time_reference(in);
  const ScannedVariable& tref = *tref_occ.variable;
  std::optional<TimeUnitsReconciler> reconciler;
  if (tref.time) {
    reconciler.emplace(*tref.time,
                       fmt::format("{}: variable '{}'", in.path(tref_occ.file), tref.name));
  }
  const std::vector<std::map<double, VariableLocation>> steps =
      locate_time_steps(in, tref_occ, reconciler);
  const std::vector<double> merged = common_time_steps(in, steps, reconciler);
  const std::size_t n = merged.size();
  const StepRange range = requested_steps(options, n);

  if (tref.time) {
    catalog.time.name = tref.time->name;
    catalog.time.units = reconciler->units();
    catalog.time.calendar = reconciler->calendar();
  }
  catalog.time.values.assign(merged.begin() + static_cast<std::ptrdiff_t>(range.first),
                             merged.begin() + static_cast<std::ptrdiff_t>(range.last) + 1);
  catalog.locations.resize(in.names.size());
  for (std::size_t v = 0; v < in.names.size(); ++v) {
    for (double t : catalog.time.values) catalog.locations[v].push_back(steps[v].at(t));
  }

  VerticalDetection vertical = detect_vertical_geometry(catalog, options);
  catalog.vertical_geometry = std::move(vertical.geometry);
  catalog.surface = std::move(vertical.surface);
  if (const auto& g = catalog.vertical_geometry) {
    spdlog::info("vertical geometry: {} from {} ({}{})",
                 g->quantity == VerticalGeometrySource::Quantity::kHeight ? "height" : "pressure",
                 g->formula, fmt::join(g->sources, ", "),
                 g->varies_in_time ? ", varies in time" : "");
  }
  if (catalog.surface) spdlog::info("surface height: '{}'", catalog.surface->variable);
  if (const auto& c = catalog.curvilinear) {
    spdlog::info("curvilinear grid placed by 2-D '{}' and '{}'", c->lon_variable, c->lat_variable);
  }

  const std::vector<std::string>& names = in.names;
  spdlog::info("{} input file{}: {} variable{} ({}) on a {} x {} x {} grid ({} levels), {} of {} "
               "time step{}",
               in.files.size(), in.files.size() == 1 ? "" : "s", names.size(),
               names.size() == 1 ? "" : "s", fmt::join(names, ", "), catalog.x.size(),
               catalog.y.size(), catalog.z.size(), axis_kind_name(catalog.z.kind),
               catalog.time.size(), n, n == 1 ? "" : "s");
  return catalog;
}

// Which side holds each variable asked for: a name on both sides, or on neither, is an
// error; a side none is asked from holds nothing for the conversion.
struct RequestedBySide {
  std::vector<std::string> grib, netcdf;
};

RequestedBySide requested_by_side(const std::vector<std::string>& requested,
                                  const std::vector<GribScan>& scans,
                                  const std::vector<ScannedFile>& files) {
  const std::vector<std::string> grib_names = grib_variable_names(scans);
  RequestedBySide out;
  for (const std::string& asked : requested) {
    std::string_view name = asked;
    while (!name.empty() && name.front() == '/') name.remove_prefix(1);
    const bool in_grib =
        std::find(grib_names.begin(), grib_names.end(), name) != grib_names.end();
    const ScannedFile* in_netcdf = nullptr;
    for (const auto& f : files) {
      if (f.find(name) != nullptr) {
        in_netcdf = &f;
        break;
      }
    }
    if (in_grib && in_netcdf) {
      const auto scan = std::find_if(scans.begin(), scans.end(), [&](const GribScan& s) {
        const auto n = grib_variable_names({s});
        return std::find(n.begin(), n.end(), name) != n.end();
      });
      throw make_error(ErrorCode::kInvalidInput,
                       "variable '{}' is in GRIB input {} and in netCDF input {}: every variable "
                       "of a conversion comes from one format; leave one of the files out",
                       name, scan->path.string(), in_netcdf->source.path);
    }
    if (!in_grib && !in_netcdf) {
      throw make_error(ErrorCode::kNotFound,
                       "variable '{}' is in no input: neither a 3-D variable of the GRIB inputs "
                       "({}: {}) nor a variable of the netCDF inputs ({} ...)",
                       name, scans.front().path.string(), fmt::join(grib_names, ", "),
                       files.front().source.path);
    }
    // grib_catalog matches names exactly; select_variables takes the leading '/' itself.
    if (in_grib) {
      out.grib.emplace_back(name);
    } else {
      out.netcdf.push_back(asked);
    }
  }
  if (!requested.empty() && (out.grib.empty() || out.netcdf.empty())) {
    const bool grib_idle = out.grib.empty();
    throw make_error(ErrorCode::kInvalidArgument,
                     "{}: none of the variables asked for ({}) is in the {} inputs; leave the {} "
                     "files out of the conversion",
                     grib_idle ? scans.front().path.string() : files.front().source.path,
                     fmt::join(requested, ", "), grib_idle ? "GRIB" : "netCDF",
                     grib_idle ? "GRIB" : "netCDF");
  }
  return out;
}

// GRIB and netCDF inputs of one conversion: each format's catalog of the whole time
// range, joined (ingest/mixed_catalog.h), then the steps asked for.
InputCatalog mixed_catalog(const InputsByFormat& by_format, const ScanOptions& options) {
  std::vector<GribScan> scans;
  for (const auto& path : by_format.grib) scans.push_back(scan_grib_file(path));
  std::vector<ScannedFile> files = scan_distinct_files(by_format.netcdf);
  const RequestedBySide requested = requested_by_side(options.variables, scans, files);
  ScanOptions side = options;
  side.first_step.reset();
  side.last_step.reset();
  side.variables = requested.grib;
  const InputCatalog grib = grib_catalog(scans, side);
  side.variables = requested.netcdf;
  const InputCatalog netcdf = netcdf_catalog(std::move(files), side);
  InputCatalog c = merge_grib_and_netcdf(grib, netcdf, by_format.grib_first, options);
  if (options.variables.empty()) return c;
  // The variables in the order asked for, as from inputs of one format.
  std::vector<VariableMeta> variables;
  std::vector<std::vector<VariableLocation>> locations;
  for (const std::string& name : options.variables) {
    const std::size_t v = c.variable_index(name);
    variables.push_back(std::move(c.variables[v]));
    locations.push_back(std::move(c.locations[v]));
  }
  c.variables = std::move(variables);
  c.locations = std::move(locations);
  return c;
}

}  // namespace

InputCatalog InputCatalog::as_in_files() const {
  InputCatalog c = *this;
  if (repeats_first_column()) {
    c.x.values.pop_back();
    c.x.periodic = false;
  }
  c.source_nx = c.x.size();
  return c;
}

std::size_t InputCatalog::variable_index(std::string_view name) const {
  std::string_view n = name;
  while (!n.empty() && n.front() == '/') n.remove_prefix(1);
  for (std::size_t i = 0; i < variables.size(); ++i) {
    if (variables[i].name == n) return i;
  }
  std::vector<std::string> names;
  for (const auto& v : variables) names.push_back(v.name);
  throw make_error(ErrorCode::kNotFound, "variable '{}' is not among the converted variables ({})",
                   name, fmt::join(names, ", "));
}

InputCatalog scan_inputs(const std::vector<std::filesystem::path>& inputs,
                         const ScanOptions& options) {
  if (inputs.empty()) throw make_error(ErrorCode::kInvalidArgument, "no input files given");
  const InputsByFormat by_format = inputs_by_format(inputs);
  if (by_format.grib.empty()) return netcdf_catalog(scan_distinct_files(inputs), options);
  // GRIB places its levels from its own keys (pv, HHL): the netCDF options would be
  // silently ignored.
  if (options.height_var || !options.formula_constants.empty()) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "{}: {} applies to netCDF input only; GRIB levels are placed from the "
                     "messages' own keys (hybrid pv with lnsp or sp, HHL for "
                     "generalVerticalLayer); leave the option out",
                     by_format.grib.front().string(),
                     options.height_var ? "--height-var" : "--formula-term");
  }
  if (by_format.netcdf.empty()) return grib_catalog(inputs, options);
  return mixed_catalog(by_format, options);
}

}  // namespace strielad::ingest
