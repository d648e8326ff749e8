// SPDX-License-Identifier: Apache-2.0
// The grib suite's harness in quick mode: the three contenders convert one round of a
// tiny sample; where grib_to_netcdf is installed, its route gives the same level-0 samples
// as the direct GRIB conversion, and both are within 16-bit packing of the NetCDF sample.
#include <gtest/gtest.h>

#include <filesystem>

#include "bench/grib_bench.h"
#include "bench/process_runner.h"

namespace strielad::testing {
namespace {

TEST(GribSuiteQuickTest, ContendersConvertAndAgree) {
  bench::GribBenchOptions o = bench::quick_grib_options({});
  o.work = std::filesystem::temp_directory_path() / "strielad_grib_suite_quick_test";
  std::filesystem::remove_all(o.work);
  const auto report = bench::run_grib_bench(o);
  ASSERT_EQ(report.contenders.size(), 5u);
  const auto& a = report.contenders[0];
  const auto& c = report.contenders[4];
  ASSERT_EQ(a.seconds.size(), 1u);
  ASSERT_EQ(c.seconds.size(), 1u);
  EXPECT_GT(a.output_bytes, 0u);
  EXPECT_GT(report.grib_bytes, 0u);
  EXPECT_LT(report.grib_bytes, report.netcdf_bytes);
  EXPECT_TRUE(report.a_vs_c.problem.empty()) << report.a_vs_c.problem;
  EXPECT_EQ(report.a_vs_c.missing_mismatches, 0u);
  EXPECT_EQ(report.a_vs_c.variables, 8u);
  EXPECT_LE(report.a_vs_c.max_relative_difference, 1.0 / 65535 + 1e-5);
  if (bench::find_program("grib_to_netcdf")) {
    EXPECT_TRUE(report.b_failure.empty()) << report.b_failure;
    EXPECT_TRUE(report.a_vs_b.equal())
        << report.a_vs_b.problem << " max difference " << report.a_vs_b.max_abs_difference;
    EXPECT_EQ(report.contenders[3].seconds.size(), 1u);
  }
  const auto tables = bench::grib_tables(report);
  ASSERT_EQ(tables.size(), 2u);
  EXPECT_EQ(tables[0].rows.size(), report.b_failure.empty() ? 5u : 2u);
  std::filesystem::remove_all(o.work);
}

}  // namespace
}  // namespace strielad::testing
