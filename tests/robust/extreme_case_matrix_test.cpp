// SPDX-License-Identifier: Apache-2.0
// Every case of the robustness matrix (docs/robustness.md) through conversion,
// verification, statistics, coarse levels, extraction, the server and advection: each
// stage must end exactly as the case expects (ok, or a clear error naming what is wrong);
// nothing crashes, hangs or emits NaN where it must not.
#include <gtest/gtest.h>

#include <cctype>
#include <set>

#include "robust/case_runner.h"
#include "robust/extreme_cases.h"
#include "support/temp_dir.h"

namespace strielad::robust {
namespace {

class ExtremeCaseMatrixTest : public ::testing::TestWithParam<std::string> {};

TEST_P(ExtremeCaseMatrixTest, EveryStageEndsAsExpected) {
  testing::TempDir dir;
  const ExtremeCase c = extreme_case(GetParam());
  RunOptions o;
  o.work_dir = dir.path();
  o.threads = 2;
  const CaseReport r = run_case(c, o);
  ASSERT_EQ(r.stages.size(), kStages.size());
  for (const auto& deviation : r.deviations()) ADD_FAILURE() << c.name << ": " << deviation;
  for (const auto& s : r.stages) {
    // A stage that ran and passed says what it checked; a refusal says why.
    if (s.outcome == Outcome::kOk || s.outcome == Outcome::kClearError) {
      EXPECT_FALSE(s.detail.empty()) << c.name << " " << stage_name(s.stage);
    }
  }
}

std::vector<std::string> case_names() {
  std::vector<std::string> names;
  for (const auto& c : extreme_cases()) names.push_back(c.name);
  return names;
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name;
  for (char ch : info.param) name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Cases, ExtremeCaseMatrixTest, ::testing::ValuesIn(case_names()), test_name);

TEST(ExtremeCaseListTest, NamesAreUniqueAndEveryCaseSaysWhatItExpects) {
  std::set<std::string> names;
  for (const auto& c : extreme_cases()) {
    EXPECT_TRUE(names.insert(c.name).second) << c.name;
    EXPECT_FALSE(c.extreme.empty()) << c.name;
    EXPECT_FALSE(c.expected_text.empty()) << c.name;
    EXPECT_FALSE(c.limits.empty()) << c.name;
    for (const auto& [stage, e] : c.expected) {
      if (e.outcome == Outcome::kClearError) {
        EXPECT_FALSE(e.message_part.empty()) << c.name << " " << stage_name(stage);
      }
    }
  }
  EXPECT_GE(names.size(), 20u);
}

}  // namespace
}  // namespace strielad::robust
