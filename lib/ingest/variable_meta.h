// SPDX-License-Identifier: Apache-2.0
// The CF attributes of a data variable that decide how its raw samples become values:
// _FillValue, missing_value, valid_range/valid_min/valid_max (all in packed units),
// scale_factor/add_offset, and the store type that keeps the unpacked values exactly.
// Attributes that would change every value (scale_factor 0, an empty valid range) are
// kept but marked unusable: reading samples with them is refused.
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
  // A NaN _FillValue or missing_value is kept: NaN samples are then missing.
  std::optional<long double> fill_value;
  std::vector<long double> missing_values;
  // A NaN bound bounds nothing (every comparison with NaN is false) and is left out.
  std::optional<long double> valid_min, valid_max;
  std::optional<double> scale_factor, add_offset;
  std::optional<int> packing_type;  // nc_type of scale_factor (else add_offset)
  // No _FillValue attribute: the netCDF default fill of the type counts as missing
  // (netCDF4-python behaviour), except for byte types and variables written NOFILL.
  std::optional<long double> default_fill;
  // Why no sample can be converted with these attributes, naming the file, variable and
  // attribute: scale_factor 0 (every value would be add_offset) or not finite, add_offset
  // not finite, valid_min above valid_max or a bound that excludes every finite value
  // (every value would be missing). Empty when usable.
  std::string unusable;

  bool packed() const { return scale_factor.has_value() || add_offset.has_value(); }
};

// Reads the attributes of variable `varid` in group `grpid` and sets `unusable` when they
// cannot convert values (the variable may still be scanned and listed). Caller holds
// netcdf_mutex().
CfValueAttributes read_value_attributes(int grpid, int varid);

// Adds `offset` to every value `a` unpacks (folded into add_offset): the readers of a
// derived variable (VariableMeta::value_offset). Nothing for 0.
void add_value_offset(CfValueAttributes& a, double offset);

// \error kInvalidInput with `a.unusable` when it is set.
void check_usable(const CfValueAttributes& a);

// The store type rule: float -> float32, double -> float64; packed integers -> the type
// of scale_factor/add_offset (float -> float32, double -> float64, integer -> float64);
// plain byte/short/ubyte/ushort -> float32, int/uint/int64/uint64 -> float64.
DType store_type_for(int var_type, std::optional<int> packing_type);

// The netCDF default fill value of a numeric type (NC_FILL_FLOAT...).
long double netcdf_default_fill(int type);

// VariableMeta of variable `varid`, named `store_name`. Caller holds netcdf_mutex().
VariableMeta read_variable_meta(int grpid, int varid, const std::string& store_name);

}  // namespace strielad::ingest
