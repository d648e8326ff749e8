// SPDX-License-Identifier: Apache-2.0
#include "ingest/ln_pressure_axis.h"

#include <fmt/format.h>
#include <netcdf.h>

#include <cmath>
#include <optional>

#include "core/error.h"
#include "grid/units.h"
#include "ingest/cf_attributes.h"
#include "ingest/formula_terms.h"
#include "ingest/netcdf_file.h"

namespace strielad::ingest {
namespace {

// Variable `name` in group `grpid` or the nearest ancestor that holds one.
std::optional<VariableRef> variable_in_scope(int grpid, const std::string& name) {
  for (std::optional<int> g = grpid; g; g = parent_group(*g)) {
    int varid = -1;
    if (nc_inq_varid(*g, name.c_str(), &varid) == NC_NOERR) return VariableRef{*g, varid};
  }
  return std::nullopt;
}

}  // namespace

std::vector<double> ln_pressure_levels(double p0_pa, std::span<const double> lev,
                                       std::string_view context) {
  if (!std::isfinite(p0_pa) || p0_pa <= 0) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: p0 is {} Pa; p = p0 * exp(-lev) needs a positive p0", context, p0_pa);
  }
  std::vector<double> p;
  p.reserve(lev.size());
  for (std::size_t k = 0; k < lev.size(); ++k) {
    if (!std::isfinite(lev[k])) {
      throw make_error(ErrorCode::kInvalidInput, "{}: lev of level {} is {}, not a finite number",
                       context, k, lev[k]);
    }
    const double pk = p0_pa * std::exp(-lev[k]);
    if (!std::isfinite(pk) || pk <= 0) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: level {} (lev {}) gives p = p0 * exp(-lev) = {} Pa, not a positive "
                       "finite pressure",
                       context, k, lev[k], pk);
    }
    p.push_back(pk);
  }
  for (std::size_t k = 2; k < p.size(); ++k) {
    if ((p[k] > p[k - 1]) != (p[1] > p[0])) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: levels {} .. {} (lev {}, {}, {}) give pressures {}, {}, {} Pa: not "
                       "strictly monotonic",
                       context, k - 2, k, lev[k - 2], lev[k - 1], lev[k], p[k - 2], p[k - 1], p[k]);
    }
  }
  for (std::size_t k = 1; k < p.size(); ++k) {
    if (p[k] == p[k - 1]) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: levels {} and {} (lev {} and {}) give the same pressure {} Pa: not "
                       "strictly monotonic",
                       context, k - 1, k, lev[k - 1], lev[k], p[k]);
    }
  }
  return p;
}

Axis read_ln_pressure_axis(int grpid, int varid, const std::string& file) {
  const std::string name = variable_name(grpid, varid);
  const std::string formula_terms = text_attribute_or_empty(grpid, varid, "formula_terms");
  const std::string context =
      fmt::format("{}: z coordinate '{}' ({}, formula_terms \"{}\")", file, name,
                  kLnPressureCoordinate, formula_terms);
  std::optional<std::string> p0_name, lev_name;
  for (const FormulaTerm& t : parse_formula_terms(formula_terms, context)) {
    if (t.term == "p0") p0_name = t.variable;
    if (t.term == "lev") lev_name = t.variable;
  }
  for (const auto& [term, named] : {std::pair{"p0", p0_name}, std::pair{"lev", lev_name}}) {
    if (!named) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: no '{}' term; {} needs the terms p0 and lev (p = p0 * exp(-lev))",
                       context, term, kLnPressureCoordinate);
    }
  }
  auto find = [&](const char* term, const std::string& variable) {
    const auto ref = variable_in_scope(grpid, variable);
    if (!ref) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: term '{}' names variable '{}', which the file does not hold", context,
                       term, variable);
    }
    if (!is_numeric_type(variable_type(ref->grpid, ref->varid))) {
      throw make_error(ErrorCode::kInvalidInput, "{}: term '{}' variable '{}' is not numeric",
                       context, term, variable);
    }
    return *ref;
  };

  const VariableRef p0 = find("p0", *p0_name);
  const std::vector<double> p0_values =
      read_all_as_double(p0.grpid, p0.varid, fmt::format("{}: p0 variable '{}'", file, *p0_name));
  if (p0_values.size() != 1) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: p0 variable '{}' holds {} values; p0 is a scalar", context, *p0_name,
                     p0_values.size());
  }
  const std::string p0_units = text_attribute_or_empty(p0.grpid, p0.varid, "units");
  const std::optional<double> pascals =
      p0_units.empty() ? std::optional<double>(1.0) : pascals_per_pressure_unit(p0_units);
  if (!pascals) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: p0 variable '{}' has units '{}', not a pressure unit (Pa, hPa...)",
                     context, *p0_name, p0_units);
  }

  const VariableRef lev = find("lev", *lev_name);
  if (variable_dimids(lev.grpid, lev.varid) != variable_dimids(grpid, varid)) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: lev variable '{}' does not lie on the dimension of '{}' alone", context,
                     *lev_name, name);
  }
  const std::vector<double> lev_values = read_all_as_double(
      lev.grpid, lev.varid, fmt::format("{}: lev variable '{}'", file, *lev_name));

  Axis a;
  a.name = name;
  a.kind = AxisKind::kPressure;
  a.units = "Pa";
  a.standard_name = "air_pressure";
  a.long_name = fmt::format("air pressure p0 * exp(-lev) ({} '{}', p0 {} Pa)",
                            kLnPressureCoordinate, name, p0_values[0] * *pascals);
  a.positive = "down";
  a.values = ln_pressure_levels(p0_values[0] * *pascals, lev_values, context);
  return a;
}

}  // namespace strielad::ingest
