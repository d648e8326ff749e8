// SPDX-License-Identifier: Apache-2.0
// The advect suite's harness in quick mode: every flow and integrator runs, errors are
// measured against the exact trajectories, tighter settings cost more evaluations, and
// explicit Euler beyond its stability limit on the stiff flow stops flagged instead of
// reporting an error.
#include <gtest/gtest.h>

#include <cmath>

#include "bench/advect_suite.h"

namespace strielad::testing {
namespace {

TEST(AdvectSuiteQuickTest, EveryFlowAndMethodIsMeasured) {
  bench::AdvectSuiteOptions o;
  o.quick = true;
  const auto report = bench::run_advect_suite(o);
  ASSERT_FALSE(report.runs.empty());
  int flows_with_all_methods = 0;
  std::string flow;
  bool euler = false, rk4 = false, dopri = false;
  for (const auto& r : report.runs) {
    if (r.flow != flow) {
      flows_with_all_methods += euler && rk4 && dopri;
      flow = r.flow;
      euler = rk4 = dopri = false;
    }
    euler |= r.method == "euler";
    rk4 |= r.method == "rk4";
    dopri |= r.method == "dopri5";
    EXPECT_GT(r.evaluations, 0u) << r.flow << " " << r.method << " " << r.setting;
    EXPECT_EQ(r.trajectories, 2);
  }
  flows_with_all_methods += euler && rk4 && dopri;
  EXPECT_EQ(flows_with_all_methods, 5);
  // Rotation with the adaptive pair: the tighter tolerance is more accurate and dearer.
  const bench::AdvectRun* loose = nullptr;
  const bench::AdvectRun* tight = nullptr;
  for (const auto& r : report.runs) {
    if (r.flow.starts_with("solid-body") && r.method == "dopri5") (loose ? tight : loose) = &r;
  }
  ASSERT_TRUE(loose && tight);
  EXPECT_LT(tight->max_error_m, loose->max_error_m);
  EXPECT_GT(tight->evaluations, loose->evaluations);
  EXPECT_LT(tight->max_error_m, 0.01);
  // Euler at 2.5/k on the stiff flow (the second stiff setting in quick mode is 1/k:
  // stable) - and every run reports either an error or why it stopped.
  for (const auto& r : report.runs) {
    EXPECT_TRUE(!std::isnan(r.max_error_m) || r.reached < r.trajectories) << r.flow << r.setting;
  }
  const auto tables = bench::advect_report_tables(report);
  EXPECT_EQ(tables.size(), 6u);
}

}  // namespace
}  // namespace strielad::testing
