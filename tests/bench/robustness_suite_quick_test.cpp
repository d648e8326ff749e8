// SPDX-License-Identifier: Apache-2.0
// The robustness suite's harness in quick mode: its cases run every stage, end as
// expected, and the tables and JSON carry every stage's outcome and detail.
#include <gtest/gtest.h>

#include "bench/robustness_suite.h"
#include "support/expect_error.h"
#include "support/temp_dir.h"

namespace strielad::testing {
namespace {

TEST(RobustnessSuiteQuickTest, QuickCasesEndAsExpected) {
  TempDir dir;
  bench::RobustnessSuiteOptions o;
  o.quick = true;
  o.work_dir = dir / "work";
  const auto report = bench::run_robustness_suite(o);
  ASSERT_EQ(report.cases.size(), bench::quick_robustness_cases().size());
  EXPECT_EQ(report.deviating(), 0u);
  for (const auto& c : report.cases) {
    EXPECT_EQ(c.stages.size(), 7u) << c.name;
    for (const auto& d : c.deviations()) ADD_FAILURE() << c.name << ": " << d;
  }
  const auto tables = bench::robustness_report_tables(report);
  ASSERT_EQ(tables.size(), 3u);
  EXPECT_EQ(tables[0].rows.size(), report.cases.size());
  EXPECT_EQ(tables[0].columns.size(), 10u);  // case, 7 stages, as expected, seconds
  // The refused cases appear in the details with their messages.
  bool refusal = false;
  for (const auto& row : tables[2].rows) {
    refusal = refusal || std::get<std::string>(row[0].value) == "nan-inf-refused";
  }
  EXPECT_TRUE(refusal);
  const auto json = bench::robustness_report_json(report, tables);
  EXPECT_EQ(json["suite"], "robustness");
  EXPECT_EQ(json["deviating_cases"], 0);
  EXPECT_EQ(json["cases"].size(), report.cases.size());
  EXPECT_EQ(json["cases"][0]["stages"].size(), 7u);
}

TEST(RobustnessSuiteQuickTest, UnknownCaseIsNamed) {
  bench::RobustnessSuiteOptions o;
  o.cases = {"no-such-case"};
  expect_error([&] { bench::run_robustness_suite(o); }, ErrorCode::kNotFound,
               {"no robustness case 'no-such-case'", "baseline"});
}

}  // namespace
}  // namespace strielad::testing
