// SPDX-License-Identifier: Apache-2.0
#include "ingest/vertical_geometry.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>

#include "core/error.h"
#include "grid/units.h"
#include "ingest/formula_terms.h"

namespace strielad::ingest {
namespace {

std::string compact_lower(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (std::isspace(static_cast<unsigned char>(c)) == 0) {
      out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
    }
  }
  return out;
}

// The factor that takes a term's values to the SI unit of what it measures.
double si_factor(const FormulaTermSpec& spec, const std::string& variable, const std::string& units,
                 std::string_view formula) {
  if (spec.units == TermUnits::kDimensionless) return 1.0;
  if (units.empty()) return 1.0;  // CF terms without units: taken as Pa or m
  const std::optional<double> f = spec.units == TermUnits::kPressure
                                      ? pascals_per_pressure_unit(units)
                                      : metres_per_height_unit(units);
  if (!f) {
    throw make_error(
        ErrorCode::kInvalidInput, "variable '{}' (term '{}' of {}) has units '{}', not a {} unit",
        variable, spec.term, formula, units,
        spec.units == TermUnits::kPressure ? "pressure (Pa, hPa...)" : "length (m, km)");
  }
  return *f;
}

void check_size(const TermValues& v, std::size_t expected, const std::string& variable,
                std::string_view what) {
  if (v.values.size() != expected) {
    throw make_error(ErrorCode::kInvalidInput,
                     "variable '{}' ({}) holds {} values where {} were expected (file changed "
                     "since it was scanned?)",
                     variable, what, v.values.size(), expected);
  }
}

// Formula "variable": the sum of the sources (heights, or geopotentials), averaged from
// half levels when a source has one level more than the grid.
void evaluate_from_variables(const VerticalGeometrySource& g, TermSource& terms, std::size_t step,
                             std::size_t z0, std::size_t z1, const Dims3& dims,
                             std::span<double> out) {
  const std::size_t plane = dims.x * dims.y;
  std::fill(out.begin(), out.end(), 0.0);
  for (const std::string& source : g.sources) {
    const std::size_t levels = terms.levels(source);
    const bool half = levels == dims.z + 1;
    if (!half && levels != dims.z) {
      throw make_error(ErrorCode::kInvalidInput,
                       "height variable '{}' has {} levels; the grid has {} (or {} half levels)",
                       source, levels, dims.z, dims.z + 1);
    }
    const TermValues v = terms.read(source, step, z0, half ? z1 + 1 : z1);
    check_size(v, (z1 - z0 + (half ? 1 : 0)) * plane, source, "height");
    std::optional<double> f = metres_per_height_unit(v.units);
    if (f && *f == 1.0 / kStandardGravity && g.geopotential_gravity > 0) {
      f = 1.0 / g.geopotential_gravity;
    }
    if (!f) {
      throw make_error(ErrorCode::kInvalidInput,
                       "height variable '{}' has units '{}'; a height needs m, km or gpm, a "
                       "geopotential m2 s-2",
                       source, v.units);
    }
    for (std::size_t k = 0; k < z1 - z0; ++k) {
      for (std::size_t s = 0; s < plane; ++s) {
        const double h = half ? 0.5 * (v.values[k * plane + s] + v.values[(k + 1) * plane + s])
                              : v.values[k * plane + s];
        out[k * plane + s] += h * *f;
      }
    }
  }
}

// A CF formula: the values of each term, scaled to SI units.
struct FormulaValues {
  std::map<std::string, std::vector<double>> values;
  const std::vector<double>& operator[](const std::string& term) const { return values.at(term); }
  bool has(const std::string& term) const { return values.count(term) > 0; }
};

FormulaValues read_terms(const VerticalGeometrySource& g, const FormulaDefinition& formula,
                         TermSource& terms, std::size_t step, std::size_t z0, std::size_t z1,
                         const Dims3& dims) {
  std::vector<std::string> given;
  for (const auto& [term, variable] : g.terms) given.push_back(term);
  for (const auto& [term, value] : g.constants) given.push_back(term);
  const auto set = complete_term_set(formula, given);
  if (!set) {
    throw make_error(ErrorCode::kInvalidInput, "{} needs the terms {}; given: {}",
                     formula.standard_name, describe_term_sets(formula), fmt::join(given, ", "));
  }
  FormulaValues out;
  for (const FormulaTermSpec& spec : *set) {
    const std::string term(spec.term);
    if (auto c = g.constants.find(term); c != g.constants.end()) {
      out.values[term] = {c->second};
      continue;
    }
    const std::string& variable = g.terms.at(term);
    TermValues v;
    std::size_t expected = 1;
    switch (spec.shape) {
      case TermShape::kLevels:
        v = terms.read(variable, step, z0, z1);
        expected = z1 - z0;
        break;
      case TermShape::kPlane:
        v = terms.read(variable, step, 0, 0);
        expected = dims.x * dims.y;
        break;
      case TermShape::kScalar:
        v = terms.read(variable, step, 0, 1);
        break;
    }
    check_size(v, expected, variable, fmt::format("term '{}' of {}", term, formula.standard_name));
    const double f = si_factor(spec, variable, v.units, formula.standard_name);
    for (double& x : v.values) x *= f;
    out.values[term] = std::move(v.values);
  }
  return out;
}

void evaluate_formula(const VerticalGeometrySource& g, TermSource& terms, std::size_t step,
                      std::size_t z0, std::size_t z1, const Dims3& dims, std::span<double> out) {
  const FormulaDefinition* formula = find_formula(g.formula);
  if (formula == nullptr) {
    throw make_error(ErrorCode::kUnsupported,
                     "vertical coordinate formula '{}' is not supported (supported: {})", g.formula,
                     supported_formulas());
  }
  const FormulaValues t = read_terms(g, *formula, terms, step, z0, z1, dims);
  const std::size_t plane = dims.x * dims.y;
  auto each = [&](auto&& value) {
    for (std::size_t k = 0; k < z1 - z0; ++k) {
      for (std::size_t s = 0; s < plane; ++s) out[k * plane + s] = value(k, s);
    }
  };
  if (g.formula == "atmosphere_hybrid_height_coordinate") {
    const auto &a = t["a"], &b = t["b"], &orog = t["orog"];
    each([&](std::size_t k, std::size_t s) { return a[k] + b[k] * orog[s]; });
  } else if (g.formula == "atmosphere_hybrid_sigma_pressure_coordinate") {
    const auto &b = t["b"], &ps = t["ps"];
    if (t.has("ap")) {
      const auto& ap = t["ap"];
      each([&](std::size_t k, std::size_t s) { return ap[k] + b[k] * ps[s]; });
    } else {
      const auto& a = t["a"];
      const double p0 = t["p0"][0];
      each([&](std::size_t k, std::size_t s) { return a[k] * p0 + b[k] * ps[s]; });
    }
  } else if (g.formula == "atmosphere_sigma_coordinate") {
    const auto &sigma = t["sigma"], &ps = t["ps"];
    const double ptop = t["ptop"][0];
    each([&](std::size_t k, std::size_t s) { return ptop + sigma[k] * (ps[s] - ptop); });
  } else {
    throw make_error(ErrorCode::kInternal, "formula '{}' has a definition but no evaluation",
                     g.formula);
  }
}

}  // namespace

std::optional<double> metres_per_height_unit(std::string_view units) {
  if (auto m = metres_per_length_unit(units)) return m;
  const std::string u = compact_lower(units);
  if (u == "gpm" || u == "geopotential_metres" || u == "geopotential_meters") return 1.0;
  for (std::string_view geopotential : {"m2s-2", "m2/s2", "m**2s**-2", "m^2s^-2", "m^2/s^2"}) {
    if (u == geopotential) return 1.0 / kStandardGravity;
  }
  return std::nullopt;
}

void evaluate_vertical_geometry(const VerticalGeometrySource& geometry, TermSource& terms,
                                std::size_t step, std::size_t z0, std::size_t z1, const Dims3& dims,
                                std::span<double> out) {
  if (z0 > z1 || z1 > dims.z) {
    throw make_error(ErrorCode::kInvalidArgument, "level range [{}, {}) outside [0, {})", z0, z1,
                     dims.z);
  }
  const std::size_t count = (z1 - z0) * dims.y * dims.x;
  if (out.size() != count) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "output holds {} values but levels [{}, {}) of {} x {} need {}", out.size(),
                     z0, z1, dims.x, dims.y, count);
  }
  if (count == 0) return;
  if (geometry.formula == "variable") {
    evaluate_from_variables(geometry, terms, step, z0, z1, dims, out);
  } else {
    evaluate_formula(geometry, terms, step, z0, z1, dims, out);
  }
}

void evaluate_surface(const SurfaceSource& surface, TermSource& terms, const Dims3& dims,
                      std::span<double> out) {
  const std::size_t plane = dims.x * dims.y;
  if (out.size() != plane) {
    throw make_error(ErrorCode::kInvalidArgument, "output holds {} values but {} x {} need {}",
                     out.size(), dims.x, dims.y, plane);
  }
  const TermValues v = terms.read(surface.variable, std::nullopt, 0, 0);
  check_size(v, plane, surface.variable, "surface height");
  const std::optional<double> f = v.units.empty() ? 1.0 : metres_per_height_unit(v.units);
  if (!f) {
    throw make_error(ErrorCode::kInvalidInput, "surface variable '{}' has units '{}', not a height",
                     surface.variable, v.units);
  }
  for (std::size_t s = 0; s < plane; ++s) out[s] = v.values[s] * *f;
}

}  // namespace strielad::ingest
