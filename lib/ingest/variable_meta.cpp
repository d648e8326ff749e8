// SPDX-License-Identifier: Apache-2.0
#include "ingest/variable_meta.h"

#include <fmt/format.h>
#include <netcdf.h>

#include <cmath>
#include <cstring>

#include "core/error.h"
#include "ingest/cf_attributes.h"
#include "ingest/netcdf_file.h"

namespace strielad::ingest {
namespace {

// "FILE: variable 'grp/T'" for messages (the path as the file was opened).
std::string describe_variable(int grpid, int varid) {
  std::string path;
  std::size_t len = 0;
  if (nc_inq_path(grpid, &len, nullptr) == NC_NOERR) {
    path.assign(len + 1, '\0');
    if (nc_inq_path(grpid, &len, path.data()) != NC_NOERR) path.clear();
    path.resize(std::strlen(path.c_str()));
  }
  std::string name = variable_name(grpid, varid);
  if (const std::string group = group_path(grpid); !group.empty()) name = group + "/" + name;
  return path.empty() ? fmt::format("variable '{}'", name)
                      : fmt::format("{}: variable '{}'", path, name);
}

double as_double(long double v) { return static_cast<double>(v); }

// Why `a` cannot convert any sample ("" when it can): attributes that would silently
// turn every value into one constant, or every value into missing.
std::string why_unusable(const CfValueAttributes& a, bool from_valid_range) {
  if (a.scale_factor && !std::isfinite(*a.scale_factor)) {
    return fmt::format("scale_factor is {}, so no value would unpack to a finite number",
                       *a.scale_factor);
  }
  if (a.scale_factor && *a.scale_factor == 0) {
    return fmt::format("scale_factor is 0, so every value would unpack to add_offset ({})",
                       a.add_offset.value_or(0.0));
  }
  if (a.add_offset && !std::isfinite(*a.add_offset)) {
    return fmt::format("add_offset is {}, so no value would unpack to a finite number",
                       *a.add_offset);
  }
  if (a.valid_min && a.valid_max && *a.valid_min > *a.valid_max) {
    return from_valid_range
               ? fmt::format("valid_range [{}, {}] is inverted (its minimum is above its maximum), "
                             "so every value would be missing",
                             as_double(*a.valid_min), as_double(*a.valid_max))
               : fmt::format("valid_min {} is above valid_max {}, so every value would be missing",
                             as_double(*a.valid_min), as_double(*a.valid_max));
  }
  // A bound that excludes every finite value (and the infinite ones are refused as data).
  if (a.valid_min && std::isinf(*a.valid_min) && *a.valid_min > 0) {
    return fmt::format("{} is +Inf, so every value would be missing",
                       from_valid_range ? "valid_range's minimum" : "valid_min");
  }
  if (a.valid_max && std::isinf(*a.valid_max) && *a.valid_max < 0) {
    return fmt::format("{} is -Inf, so every value would be missing",
                       from_valid_range ? "valid_range's maximum" : "valid_max");
  }
  return {};
}

// A bound as CF applies it: a NaN bound excludes nothing, so it is no bound.
std::optional<long double> bound(long double v) {
  if (std::isnan(v)) return std::nullopt;
  return v;
}

}  // namespace

long double netcdf_default_fill(int type) {
  switch (type) {
    case NC_BYTE: return NC_FILL_BYTE;
    case NC_SHORT: return NC_FILL_SHORT;
    case NC_INT: return NC_FILL_INT;
    case NC_FLOAT: return static_cast<long double>(NC_FILL_FLOAT);
    case NC_DOUBLE: return static_cast<long double>(NC_FILL_DOUBLE);
    case NC_UBYTE: return NC_FILL_UBYTE;
    case NC_USHORT: return NC_FILL_USHORT;
    case NC_UINT: return NC_FILL_UINT;
    case NC_INT64: return static_cast<long double>(NC_FILL_INT64);
    case NC_UINT64: return static_cast<long double>(NC_FILL_UINT64);
    default: return 0;
  }
}

CfValueAttributes read_value_attributes(int grpid, int varid) {
  CfValueAttributes a;
  a.type = variable_type(grpid, varid);

  if (auto fill = numeric_attribute(grpid, varid, "_FillValue"); !fill.empty()) {
    a.fill_value = fill.front();
  }
  a.missing_values = numeric_attribute(grpid, varid, "missing_value");
  const auto range = numeric_attribute(grpid, varid, "valid_range");
  const bool from_valid_range = range.size() >= 2;
  if (from_valid_range) {
    a.valid_min = bound(range[0]);
    a.valid_max = bound(range[1]);
  } else {
    if (auto v = numeric_attribute(grpid, varid, "valid_min"); !v.empty()) a.valid_min = bound(v[0]);
    if (auto v = numeric_attribute(grpid, varid, "valid_max"); !v.empty()) a.valid_max = bound(v[0]);
  }
  if (auto v = numeric_attribute(grpid, varid, "scale_factor"); !v.empty()) {
    a.scale_factor = static_cast<double>(v[0]);
    a.packing_type = attribute_type(grpid, varid, "scale_factor");
  }
  if (auto v = numeric_attribute(grpid, varid, "add_offset"); !v.empty()) {
    a.add_offset = static_cast<double>(v[0]);
    if (!a.packing_type) a.packing_type = attribute_type(grpid, varid, "add_offset");
  }
  if (!a.fill_value && is_numeric_type(a.type) && a.type != NC_BYTE && a.type != NC_UBYTE) {
    int no_fill = 0;
    if (nc_inq_var_fill(grpid, varid, &no_fill, nullptr) != NC_NOERR) no_fill = 0;
    if (no_fill != 1) a.default_fill = netcdf_default_fill(a.type);
  }
  if (std::string why = why_unusable(a, from_valid_range); !why.empty()) {
    a.unusable = fmt::format("{}: {}; refusing to convert it (correct or delete the attribute)",
                             describe_variable(grpid, varid), why);
  }
  return a;
}

void check_usable(const CfValueAttributes& a) {
  if (!a.unusable.empty()) throw Error(ErrorCode::kInvalidInput, a.unusable);
}

DType store_type_for(int var_type, std::optional<int> packing_type) {
  if (packing_type) {
    if (*packing_type == NC_FLOAT && var_type != NC_DOUBLE) return DType::kFloat32;
    return DType::kFloat64;  // double or integer packing attributes, or double data
  }
  switch (var_type) {
    case NC_FLOAT:
    case NC_BYTE:
    case NC_SHORT:
    case NC_UBYTE:
    case NC_USHORT:
      return DType::kFloat32;
    default:
      return DType::kFloat64;
  }
}

void add_value_offset(CfValueAttributes& a, double offset) {
  if (offset != 0) a.add_offset = a.add_offset.value_or(0.0) + offset;
}

VariableMeta read_variable_meta(int grpid, int varid, const std::string& store_name) {
  const CfValueAttributes a = read_value_attributes(grpid, varid);
  VariableMeta m;
  m.name = store_name;
  m.units = text_attribute_or_empty(grpid, varid, "units");
  m.long_name = text_attribute_or_empty(grpid, varid, "long_name");
  m.standard_name = text_attribute_or_empty(grpid, varid, "standard_name");
  m.store_type = store_type_for(a.type, a.packing_type);
  m.source_type = std::string(nc_type_name(a.type));
  if (a.fill_value) m.fill_value = static_cast<double>(*a.fill_value);
  for (long double v : a.missing_values) m.missing_values.push_back(static_cast<double>(v));
  if (!m.missing_values.empty()) m.missing_value = m.missing_values.front();
  if (a.valid_min) m.valid_min = static_cast<double>(*a.valid_min);
  if (a.valid_max) m.valid_max = static_cast<double>(*a.valid_max);
  m.scale_factor = a.scale_factor;
  m.add_offset = a.add_offset;
  return m;
}

}  // namespace strielad::ingest
