// SPDX-License-Identifier: Apache-2.0
#include "ingest/variable_meta.h"

#include <netcdf.h>

#include "ingest/cf_attributes.h"
#include "ingest/netcdf_file.h"

namespace strielad::ingest {

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
  if (auto range = numeric_attribute(grpid, varid, "valid_range"); range.size() >= 2) {
    a.valid_min = range[0];
    a.valid_max = range[1];
  } else {
    if (auto v = numeric_attribute(grpid, varid, "valid_min"); !v.empty()) a.valid_min = v[0];
    if (auto v = numeric_attribute(grpid, varid, "valid_max"); !v.empty()) a.valid_max = v[0];
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
  return a;
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
