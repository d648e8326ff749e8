// SPDX-License-Identifier: Apache-2.0
#include "ingest/term_reader.h"

#include <fmt/format.h>
#include <netcdf.h>

#include <cmath>
#include <mutex>

#include "core/error.h"
#include "ingest/cf_attributes.h"
#include "ingest/netcdf_call.h"
#include "ingest/sample_conversion.h"
#include "ingest/variable_meta.h"

namespace strielad::ingest {
namespace {

constexpr std::size_t kMaxOpenFiles = 8;

std::string group_of(const std::string& store_name) {
  const auto slash = store_name.rfind('/');
  return slash == std::string::npos ? std::string() : store_name.substr(0, slash);
}

std::string step_text(std::optional<std::size_t> step) {
  return step ? fmt::format("time step {}", *step) : std::string("first time step");
}

}  // namespace

NcTermReader::NcTermReader(InputCatalog catalog)
    : catalog_(std::move(catalog)),
      group_(catalog_.variables.empty() ? std::string() : group_of(catalog_.variables[0].name)) {}

NcTermReader::~NcTermReader() {
  std::lock_guard lock(netcdf_mutex());
  open_.clear();
}

int NcTermReader::open_file(std::size_t file) {
  if (auto it = open_.find(file); it != open_.end()) return it->second.id();
  if (open_.size() >= kMaxOpenFiles) open_.clear();
  return open_.emplace(file, NcFile(catalog_.files[file].path)).first->second.id();
}

std::optional<TermVariable> NcTermReader::find_in_file(std::size_t file,
                                                       const std::string& variable) {
  if (absent_.count({file, variable})) return std::nullopt;
  const int ncid = open_file(file);
  int grpid = ncid;
  if (!group_.empty() && nc_inq_grp_full_ncid(ncid, ("/" + group_).c_str(), &grpid) != NC_NOERR) {
    grpid = ncid;
  }
  for (std::optional<int> g = grpid; g; g = parent_group(*g)) {
    int varid = -1;
    if (nc_inq_varid(*g, variable.c_str(), &varid) != NC_NOERR) continue;
    TermVariable t;
    t.file = file;
    t.grpid = *g;
    t.varid = varid;
    t.name = variable;
    const std::vector<int> dimids = variable_dimids(*g, varid);
    for (int d : dimids) t.dimensions.push_back(dimension_name(*g, d));
    std::size_t first = 0;
    if (!dimids.empty() &&
        ((!catalog_.time.name.empty() && t.dimensions[0] == catalog_.time.name) ||
         is_unlimited_dimension(*g, dimids[0]))) {
      t.has_time = true;
      t.time_length = dimension_length(*g, dimids[0]);
      first = 1;
    }
    for (std::size_t i = first; i < dimids.size(); ++i) {
      t.shape.push_back(dimension_length(*g, dimids[i]));
    }
    t.units = text_attribute_or_empty(*g, varid, "units");
    return t;
  }
  absent_.insert({file, variable});
  return std::nullopt;
}

std::optional<TermVariable> NcTermReader::find_locked(const std::string& variable) {
  const std::size_t data_file = catalog_.locations.empty() || catalog_.locations[0].empty()
                                    ? 0
                                    : catalog_.locations[0][0].file;
  if (auto t = find_in_file(data_file, variable)) return t;
  for (std::size_t f = 0; f < catalog_.files.size(); ++f) {
    if (f == data_file) continue;
    if (auto t = find_in_file(f, variable)) return t;
  }
  return std::nullopt;
}

std::optional<TermVariable> NcTermReader::find(const std::string& variable) {
  std::lock_guard lock(netcdf_mutex());
  return find_locked(variable);
}

std::pair<TermVariable, std::size_t> NcTermReader::locate(const std::string& variable,
                                                          std::optional<std::size_t> step) {
  std::lock_guard lock(netcdf_mutex());
  return locate_locked(variable, step);
}

std::pair<TermVariable, std::size_t> NcTermReader::locate_locked(const std::string& variable,
                                                                 std::optional<std::size_t> step) {
  if (!step) {
    auto t = find_locked(variable);
    if (!t) {
      throw make_error(ErrorCode::kInvalidInput, "variable '{}' is in none of the {} input files",
                       variable, catalog_.files.size());
    }
    if (t->has_time && t->time_length == 0) {
      throw make_error(ErrorCode::kInvalidInput, "{}: variable '{}' has no time step",
                       catalog_.files[t->file].path, variable);
    }
    return {std::move(*t), 0};
  }
  if (catalog_.locations.empty() || *step >= catalog_.locations[0].size()) {
    throw make_error(ErrorCode::kInvalidArgument, "time step {} out of range ({} steps)", *step,
                     catalog_.locations.empty() ? 0 : catalog_.locations[0].size());
  }
  const VariableLocation& loc = catalog_.locations[0][*step];
  const std::string& data_path = catalog_.files[loc.file].path;
  if (auto t = find_in_file(loc.file, variable)) {
    if (!t->has_time) return {std::move(*t), 0};
    if (loc.time_in_file >= t->time_length) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: variable '{}' has {} time steps, but the data of time step {} (value "
                       "{}) is at time index {} of this file: the vertical geometry lacks that "
                       "time step",
                       data_path, variable, t->time_length, *step,
                       *step < catalog_.time.values.size() ? catalog_.time.values[*step] : 0.0,
                       loc.time_in_file);
    }
    return {std::move(*t), loc.time_in_file};
  }
  auto t = find_locked(variable);
  if (!t) {
    throw make_error(ErrorCode::kInvalidInput, "variable '{}' is in none of the {} input files",
                     variable, catalog_.files.size());
  }
  if (t->has_time) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: variable '{}' is missing for time step {} (value {}): it varies in time "
                     "({} has it), so the file holding the data of each step must hold it too",
                     data_path, variable, *step,
                     *step < catalog_.time.values.size() ? catalog_.time.values[*step] : 0.0,
                     catalog_.files[t->file].path);
  }
  return {std::move(*t), 0};
}

std::size_t NcTermReader::levels(const std::string& variable) {
  const auto t = [&] {
    std::lock_guard lock(netcdf_mutex());
    return find_locked(variable);
  }();
  if (!t) {
    throw make_error(ErrorCode::kInvalidInput, "variable '{}' is in none of the {} input files",
                     variable, catalog_.files.size());
  }
  return t->shape.size() == 1 || t->shape.size() == 3 ? t->shape[0] : 0;
}

TermValues NcTermReader::read(const std::string& variable, std::optional<std::size_t> step,
                              std::size_t k0, std::size_t k1) {
  // One lock for locating and reading: a file closed in between would leave stale ids.
  std::lock_guard lock(netcdf_mutex());
  const auto [t, time_index] = locate_locked(variable, step);
  const std::string& path = catalog_.files[t.file].path;
  const std::string context =
      fmt::format("{}: variable '{}' (vertical geometry) {}", path, variable, step_text(step));
  std::vector<std::size_t> start, count;
  if (t.has_time) {
    start.push_back(time_index);
    count.push_back(1);
  }
  const bool has_levels = t.shape.size() == 1 || t.shape.size() == 3;
  for (std::size_t i = 0; i < t.shape.size(); ++i) {
    if (i == 0 && has_levels) {
      if (k0 > k1 || k1 > t.shape[0]) {
        throw make_error(ErrorCode::kInvalidInput, "{}: levels [{}, {}) outside its {} levels",
                         context, k0, k1, t.shape[0]);
      }
      start.push_back(k0);
      count.push_back(k1 - k0);
    } else {
      start.push_back(0);
      count.push_back(t.shape[i]);
    }
  }
  std::size_t n = 1;
  for (std::size_t c : count) n *= c;
  TermValues out;
  out.units = t.units;
  out.values.resize(n);
  const CfValueAttributes attrs = read_value_attributes(t.grpid, t.varid);
  if (!is_numeric_type(attrs.type)) {
    throw make_error(ErrorCode::kInvalidInput, "{}: has non-numeric type {}", context,
                     nc_type_name(attrs.type));
  }
  if (n > 0) {
    nc_check(nc_get_vara_double(t.grpid, t.varid, start.data(), count.data(), out.values.data()),
             context);
  }
  convert_samples<double, double>(std::span<const double>(out.values), attrs, true,
                                  std::span<double>(out.values));
  // Sample indices as (i, j, k) of the variable's own dimensions.
  const std::size_t nx = t.shape.size() >= 2 ? t.shape.back() : 1;
  const std::size_t ny = t.shape.size() >= 2 ? t.shape[t.shape.size() - 2] : 1;
  for (std::size_t s = 0; s < n; ++s) {
    if (std::isfinite(out.values[s])) continue;
    const std::size_t k = (has_levels ? k0 : 0) + s / (nx * ny);
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: sample (i {}, j {}, k {}) is missing or not finite (_FillValue, "
                     "missing_value, outside the valid range, NaN or Inf); the vertical "
                     "geometry needs every value",
                     context, s % nx, (s / nx) % ny, k);
  }
  return out;
}

}  // namespace strielad::ingest
