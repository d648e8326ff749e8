// SPDX-License-Identifier: Apache-2.0
// The CF attributes of a data variable that decide how its raw samples become values:
// _FillValue, missing_value, valid_range/valid_min/valid_max (all in packed units),
// scale_factor/add_offset, and the store type that keeps the unpacked values exactly.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "grid/axis.h"
#include "ingest/input_catalog.h"

namespace strielad::ingest {

// Exact values (integers up to 64 bits survive in long double).
struct CfValueAttributes {
  int type = 0;  // the variable's nc_type
  std::optional<long double> fill_value;
  std::vector<long double> missing_values;
  std::optional<long double> valid_min, valid_max;
  std::optional<double> scale_factor, add_offset;
  std::optional<int> packing_type;  // nc_type of scale_factor (else add_offset)
  // No _FillValue attribute: the netCDF default fill of the type counts as missing
  // (netCDF4-python behaviour), except for byte types and variables written NOFILL.
  std::optional<long double> default_fill;

  bool packed() const { return scale_factor.has_value() || add_offset.has_value(); }
};

// Reads the attributes of variable `varid` in group `grpid`. Caller holds netcdf_mutex().
CfValueAttributes read_value_attributes(int grpid, int varid);

// The store type rule: float -> float32, double -> float64; packed integers -> the type
// of scale_factor/add_offset (float -> float32, double -> float64, integer -> float64);
// plain byte/short/ubyte/ushort -> float32, int/uint/int64/uint64 -> float64.
DType store_type_for(int var_type, std::optional<int> packing_type);

// The netCDF default fill value of a numeric type (NC_FILL_FLOAT...).
long double netcdf_default_fill(int type);

// VariableMeta of variable `varid`, named `store_name`. Caller holds netcdf_mutex().
VariableMeta read_variable_meta(int grpid, int varid, const std::string& store_name);

}  // namespace strielad::ingest
