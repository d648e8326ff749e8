// SPDX-License-Identifier: Apache-2.0
// CF parametric vertical coordinates (CF conventions, appendix D): parsing a
// `formula_terms` attribute, and which terms each supported formula needs and what shape
// each term has. Pure functions: no netCDF calls.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ingest/input_catalog.h"

namespace strielad::ingest {

struct FormulaTerm {
  std::string term;      // "a", "b", "ps", "p0", "orog"...
  std::string variable;  // the variable that holds it
  friend bool operator==(const FormulaTerm&, const FormulaTerm&) = default;
};

// "a: hyam b: hybm p0: P0 ps: PS" as (term, variable) pairs, in order.
// \error kInvalidInput naming `context` for text that is not "term: variable" pairs or
// that names a term twice.
std::vector<FormulaTerm> parse_formula_terms(std::string_view text, std::string_view context);

// What a term holds along the grid.
enum class TermShape {
  kLevels,  // one value per level of the z axis: a(k), b(k), ap(k), sigma(k)
  kPlane,   // one value per column, optionally per time step: ps(n, j, i), orog(n, j, i)
  kScalar,  // one value: p0, ptop
};

// What a term's values measure, for their units.
enum class TermUnits { kDimensionless, kPressure, kLength };

struct FormulaTermSpec {
  std::string_view term;
  TermShape shape;
  TermUnits units;
};

struct FormulaDefinition {
  std::string_view standard_name;
  VerticalGeometrySource::Quantity quantity;
  // The term sets the formula accepts; the first one whose terms are all given is used
  // (atmosphere_hybrid_sigma_pressure_coordinate: a, b, ps, p0, or ap, b, ps).
  std::vector<std::vector<FormulaTermSpec>> term_sets;
};

// The supported formula of this standard_name, or nullptr.
const FormulaDefinition* find_formula(std::string_view standard_name);

// "atmosphere_hybrid_height_coordinate, atmosphere_hybrid_sigma_pressure_coordinate, ...".
std::string supported_formulas();

// The term set of `formula` that `given` (term names) completes: the first set all of
// whose terms are given, or nullopt.
std::optional<std::vector<FormulaTermSpec>> complete_term_set(
    const FormulaDefinition& formula, const std::vector<std::string>& given);

// "a, b, ps, p0 or ap, b, ps": the term sets of `formula`, for messages.
std::string describe_term_sets(const FormulaDefinition& formula);

}  // namespace strielad::ingest
