// SPDX-License-Identifier: Apache-2.0
#include "ingest/formula_terms.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>

#include "core/error.h"

namespace strielad::ingest {
namespace {

using Q = VerticalGeometrySource::Quantity;
using S = TermShape;
using U = TermUnits;

const std::vector<FormulaDefinition>& formulas() {
  static const std::vector<FormulaDefinition> kFormulas{
      // z(n,k,j,i) = a(k) + b(k) * orog(n,j,i)
      {"atmosphere_hybrid_height_coordinate",
       Q::kHeight,
       {{{"a", S::kLevels, U::kLength},
         {"b", S::kLevels, U::kDimensionless},
         {"orog", S::kPlane, U::kLength}}}},
      // p(n,k,j,i) = a(k) * p0 + b(k) * ps(n,j,i), or ap(k) + b(k) * ps(n,j,i)
      {"atmosphere_hybrid_sigma_pressure_coordinate",
       Q::kPressure,
       {{{"a", S::kLevels, U::kDimensionless},
         {"b", S::kLevels, U::kDimensionless},
         {"ps", S::kPlane, U::kPressure},
         {"p0", S::kScalar, U::kPressure}},
        {{"ap", S::kLevels, U::kPressure},
         {"b", S::kLevels, U::kDimensionless},
         {"ps", S::kPlane, U::kPressure}}}},
      // p(n,k,j,i) = ptop + sigma(k) * (ps(n,j,i) - ptop)
      {"atmosphere_sigma_coordinate",
       Q::kPressure,
       {{{"sigma", S::kLevels, U::kDimensionless},
         {"ps", S::kPlane, U::kPressure},
         {"ptop", S::kScalar, U::kPressure}}}},
  };
  return kFormulas;
}

bool is_blank(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

}  // namespace

std::vector<FormulaTerm> parse_formula_terms(std::string_view text, std::string_view context) {
  std::vector<std::string> words;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && is_blank(text[i])) ++i;
    const std::size_t b = i;
    while (i < text.size() && !is_blank(text[i])) ++i;
    if (i > b) words.emplace_back(text.substr(b, i - b));
  }
  auto malformed = [&](std::string_view why) {
    return make_error(ErrorCode::kInvalidInput,
                      "{}: formula_terms \"{}\" {}; CF writes \"term: variable\" pairs (\"a: "
                      "hyam b: hybm p0: P0 ps: PS\")",
                      context, text, why);
  };
  std::vector<FormulaTerm> out;
  for (std::size_t w = 0; w < words.size(); ++w) {
    std::string word = words[w];
    FormulaTerm t;
    if (const auto colon = word.find(':'); colon != std::string::npos && colon + 1 < word.size()) {
      // "a:hyam" written without the blank
      t.term = word.substr(0, colon);
      t.variable = word.substr(colon + 1);
    } else {
      if (word.size() < 2 || word.back() != ':')
        throw malformed(fmt::format("has '{}' where a term belongs", word));
      if (w + 1 >= words.size()) throw malformed(fmt::format("gives no variable for '{}'", word));
      t.term = word.substr(0, word.size() - 1);
      t.variable = words[++w];
      if (t.variable.find(':') != std::string::npos) {
        throw malformed(fmt::format("gives no variable for '{}'", word));
      }
    }
    for (const FormulaTerm& seen : out) {
      if (seen.term == t.term) throw malformed(fmt::format("names term '{}' twice", t.term));
    }
    out.push_back(std::move(t));
  }
  if (out.empty()) throw malformed("names no term");
  return out;
}

const FormulaDefinition* find_formula(std::string_view standard_name) {
  for (const FormulaDefinition& f : formulas()) {
    if (f.standard_name == standard_name) return &f;
  }
  return nullptr;
}

std::string supported_formulas() {
  std::vector<std::string_view> names;
  for (const FormulaDefinition& f : formulas()) names.push_back(f.standard_name);
  return fmt::format("{}", fmt::join(names, ", "));
}

std::optional<std::vector<FormulaTermSpec>> complete_term_set(
    const FormulaDefinition& formula, const std::vector<std::string>& given) {
  for (const auto& set : formula.term_sets) {
    const bool complete = std::all_of(set.begin(), set.end(), [&](const FormulaTermSpec& s) {
      return std::find(given.begin(), given.end(), s.term) != given.end();
    });
    if (complete) return set;
  }
  return std::nullopt;
}

std::string describe_term_sets(const FormulaDefinition& formula) {
  std::vector<std::string> sets;
  for (const auto& set : formula.term_sets) {
    std::vector<std::string_view> terms;
    for (const FormulaTermSpec& s : set) terms.push_back(s.term);
    sets.push_back(fmt::format("{}", fmt::join(terms, ", ")));
  }
  return fmt::format("{}", fmt::join(sets, " or "));
}

}  // namespace strielad::ingest
