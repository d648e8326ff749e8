// SPDX-License-Identifier: Apache-2.0
// parse_formula_terms and the term sets of the supported CF formulas.
#include <gtest/gtest.h>

#include "ingest/formula_terms.h"
#include "support/expect_error.h"

namespace strielad::ingest {
namespace {

using strielad::testing::expect_error;

TEST(FormulaTermsParsingTest, PairsInOrderWithOrWithoutBlanks) {
  EXPECT_EQ(parse_formula_terms("a: hyam b: hybm  p0: P0\tps:PS", "f.nc: lev"),
            (std::vector<FormulaTerm>{{"a", "hyam"}, {"b", "hybm"}, {"p0", "P0"}, {"ps", "PS"}}));
}

TEST(FormulaTermsParsingTest, MalformedTextIsRefusedNamingTheContext) {
  expect_error([] { parse_formula_terms("a: hyam b", "f.nc: lev"); }, ErrorCode::kInvalidInput,
               {"f.nc: lev", "'b'"});
  expect_error([] { parse_formula_terms("a: hyam b:", "f.nc: lev"); }, ErrorCode::kInvalidInput,
               {"no variable for 'b:'"});
  expect_error([] { parse_formula_terms("a: x a: y", "f.nc: lev"); }, ErrorCode::kInvalidInput,
               {"term 'a' twice"});
  expect_error([] { parse_formula_terms("  ", "f.nc: lev"); }, ErrorCode::kInvalidInput,
               {"names no term"});
}

TEST(FormulaTermsParsingTest, SigmaPressureAcceptsEitherTermSet) {
  const FormulaDefinition* f = find_formula("atmosphere_hybrid_sigma_pressure_coordinate");
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->quantity, VerticalGeometrySource::Quantity::kPressure);
  EXPECT_EQ(complete_term_set(*f, {"a", "b", "ps", "p0"})->size(), 4u);
  EXPECT_EQ(complete_term_set(*f, {"ap", "b", "ps"})->front().term, "ap");
  EXPECT_FALSE(complete_term_set(*f, {"a", "b", "ps"}));
  EXPECT_EQ(describe_term_sets(*f), "a, b, ps, p0 or ap, b, ps");
  EXPECT_EQ(find_formula("atmosphere_ln_pressure_coordinate"), nullptr);
  EXPECT_EQ(supported_formulas(),
            "atmosphere_hybrid_height_coordinate, atmosphere_hybrid_sigma_pressure_coordinate, "
            "atmosphere_sigma_coordinate");
}

}  // namespace
}  // namespace strielad::ingest
