// SPDX-License-Identifier: Apache-2.0
// The advect suite's harness in quick mode: every flow and integrator runs, errors are
// measured against the exact trajectories, tighter settings cost more evaluations, every
// run reports an error or why it stopped, the Rosenbrock method is far cheaper than the
// explicit ones on the stiffest flow, the sample generator's wind is measured against
// its reference, and the plot's script and data are written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

#include "bench/advect_suite.h"

namespace strielad::testing {
namespace {

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

const bench::AdvectRun* cheapest_within(const bench::AdvectSuiteReport& report,
                                        std::string_view flow_prefix, std::string_view method,
                                        double error_m) {
  const bench::AdvectRun* pick = nullptr;
  for (const auto& r : report.runs) {
    if (r.flow.starts_with(flow_prefix) && r.method == method && r.max_error_m <= error_m &&
        (!pick || r.evaluations < pick->evaluations)) {
      pick = &r;
    }
  }
  return pick;
}

TEST(AdvectSuiteQuickTest, EveryFlowAndMethodIsMeasured) {
  bench::AdvectSuiteOptions o;
  o.quick = true;
  const auto dir = std::filesystem::temp_directory_path() / "strielad_advect_quick_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  o.plot_png = dir / "advect.png";
  const auto report = bench::run_advect_suite(o);
  ASSERT_FALSE(report.runs.empty());
  ASSERT_EQ(report.flows.size(), 6u);
  for (const auto& flow : report.flows) {
    EXPECT_EQ(flow.trajectories, 2) << flow.name << ": " << flow.note;
    int with_method[4] = {};
    for (const auto& r : report.runs) {
      if (r.flow != flow.name) continue;
      with_method[0] += r.method == "euler";
      with_method[1] += r.method == "rk4";
      with_method[2] += r.method == "dopri5";
      with_method[3] += r.method == "rosenbrock";
      EXPECT_GT(r.evaluations, 0u) << r.flow << " " << r.method << " " << r.setting;
      EXPECT_EQ(r.trajectories, 2);
    }
    for (const int count : with_method) EXPECT_EQ(count, 2) << flow.name;
  }
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
  // Stiffness ratio 1e4: the Rosenbrock method reaches 1 m with a small fraction of the
  // explicit methods' evaluations.
  constexpr std::string_view kStiffest = "stiff convergence (rates 1e-3 and 10 ";
  const auto* rosenbrock = cheapest_within(report, kStiffest, "rosenbrock", 1.0);
  const auto* rk4 = cheapest_within(report, kStiffest, "rk4", 1.0);
  ASSERT_TRUE(rosenbrock && rk4);
  EXPECT_LT(20 * rosenbrock->evaluations, rk4->evaluations);
  // The generated wind against its reference: every run measured, and the tight
  // Rosenbrock setting well within a metre, closer than the loose one.
  std::vector<const bench::AdvectRun*> generated;
  for (const auto& r : report.runs) {
    if (!r.flow.starts_with("generated sample wind")) continue;
    EXPECT_TRUE(std::isfinite(r.max_error_m)) << r.method << " " << r.setting << ": " << r.stops;
    if (r.method == "rosenbrock") generated.push_back(&r);
  }
  ASSERT_EQ(generated.size(), 2u);  // rtol 1e-4, then 1e-7
  EXPECT_LT(generated[1]->max_error_m, 0.5);
  EXPECT_LT(generated[1]->max_error_m, generated[0]->max_error_m);
  const auto tables = bench::advect_report_tables(report);
  EXPECT_EQ(tables.size(), 7u);
  // The plot's data has a block per flow and method; its script names the PNG.
  EXPECT_NE(report.plot_status, "");
  const std::string data = read_file(dir / "advect.dat");
  EXPECT_NE(data.find("# generated sample wind"), std::string::npos);
  EXPECT_NE(data.find("/ rosenbrock"), std::string::npos);
  EXPECT_NE(read_file(dir / "advect.gp").find("set output 'advect.png'"), std::string::npos);
  if (report.plot_status == "written") {
    EXPECT_TRUE(std::filesystem::exists(dir / "advect.png"));
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace strielad::testing
