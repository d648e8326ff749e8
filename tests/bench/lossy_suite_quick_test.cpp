// SPDX-License-Identifier: Apache-2.0
// The lossy suite's harness in quick mode: a lossless store and one per tolerance, each
// variable's error within its tolerance and smaller stores for looser ones, cold reads and
// conversions timed, the scene cases extracted against the lossless store, the tables and
// the chart's script and data written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "bench/lossy_suite.h"
#include "support/temp_dir.h"

namespace strielad::testing {
namespace {

TEST(LossySuiteQuick, ErrorStaysWithinToleranceAndLooserIsSmaller) {
  TempDir dir;
  bench::LossySuiteOptions o = bench::quick_lossy_options({});
  o.work = dir / "work";
  o.nccopy = false;
  o.plot_png = dir / "lossy.png";
  const bench::LossySuiteReport r = bench::run_lossy_suite(o);
  ASSERT_EQ(r.runs.size(), 1 + o.fractions.size());
  EXPECT_EQ(r.runs.front().fraction, 0.0);
  for (std::size_t k = 1; k < r.runs.size(); ++k) {
    const auto& run = r.runs[k];
    EXPECT_GT(run.zfp_bricks, 0u);
    EXPECT_FALSE(run.convert_seconds.empty());
    EXPECT_GT(run.cold_read_us.count, 0u);
    ASSERT_EQ(run.variables.size(), o.variables.size());
    for (std::size_t i = 0; i < run.variables.size(); ++i) {
      const auto& v = run.variables[i];
      EXPECT_GT(v.tolerance, 0.0) << v.variable;
      EXPECT_LE(v.max_error, v.tolerance) << v.variable;
      EXPECT_LE(v.rms_error, v.max_error) << v.variable;
      EXPECT_LE(v.store_bytes, r.runs.front().variables[i].store_bytes) << v.variable;
      if (k > 1) {
        EXPECT_LE(v.store_bytes, r.runs[k - 1].variables[i].store_bytes) << v.variable;
      }
    }
    EXPECT_EQ(run.surfaces.size(), 2u);  // cloud and dense
    for (const auto& s : run.surfaces) EXPECT_TRUE(std::isfinite(s.volume_error)) << s.case_name;
  }
  const auto tables = bench::lossy_report_tables(r);
  ASSERT_EQ(tables.size(), 3u);
  EXPECT_EQ(tables[0].rows.size(), o.variables.size() * r.runs.size());
  const auto j = bench::lossy_report_json(r, tables);
  EXPECT_EQ(j["suite"], "lossy");
  EXPECT_TRUE(std::filesystem::exists(dir / "lossy.gp"));
  EXPECT_TRUE(std::filesystem::exists(dir / "lossy.dat"));
}

}  // namespace
}  // namespace strielad::testing
