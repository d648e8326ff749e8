// SPDX-License-Identifier: Apache-2.0
// The scaling suite's harness in quick mode: three grid sizes of growing cells, each
// converted and extracted at 1 and 2 threads; the threaded server and (where mpirun is
// installed) strielad-serve on two MPI ranks complete a cold cut and a scene change; more
// sub-volumes never read fewer bricks or send fewer bytes. Also the grid fractions.
#include <gtest/gtest.h>

#include <filesystem>

#include "bench/process_runner.h"
#include "bench/scaling_suite.h"
#include "core/error.h"

namespace strielad::testing {
namespace {

TEST(ScalingSuiteQuickTest, FractionsScaleTheHorizontalAxes) {
  const Dims3 full{1429, 1556, 150};
  EXPECT_EQ(bench::fraction_of_grid(full, 0.25).x, 715u);
  EXPECT_EQ(bench::fraction_of_grid(full, 0.25).y, 778u);
  EXPECT_EQ(bench::fraction_of_grid(full, 0.25).z, 150u);
  EXPECT_EQ(bench::fraction_of_grid(full, 0.5).x, 1010u);
  EXPECT_EQ(bench::fraction_of_grid(full, 0.5).y, 1100u);
  EXPECT_EQ(bench::fraction_of_grid(full, 1.0).x, 1429u);
  EXPECT_THROW(bench::fraction_of_grid(full, 0.0), Error);
  EXPECT_THROW(bench::fraction_of_grid(full, 1.5), Error);
}

TEST(ScalingSuiteQuickTest, CostGrowsWithGridAndSubvolumes) {
  bench::ScalingSuiteOptions o = bench::quick_scaling_options({});
  o.work = std::filesystem::temp_directory_path() / "strielad_scaling_suite_quick_test";
  o.server_binary = STRIELAD_SERVE_EXE;
  o.mpirun = bench::find_program("mpirun").value_or(std::filesystem::path{});
  const auto report = bench::run_scaling_suite(o);

  ASSERT_EQ(report.grids.size(), 3u);
  for (std::size_t i = 0; i < report.grids.size(); ++i) {
    const auto& g = report.grids[i];
    SCOPED_TRACE(i);
    ASSERT_EQ(g.convert.size(), 2u);
    ASSERT_EQ(g.level.size(), 2u);
    EXPECT_GT(g.convert[0].seconds.p50, 0);
    EXPECT_GT(g.store_bytes, 0u);
    EXPECT_GT(g.level_cost.extracted, 0u);
    EXPECT_EQ(g.level_cost.nodes, g.leaves);
    EXPECT_GT(g.cut_cost.nodes, 0u);
    EXPECT_LE(g.cut_cost.nodes, g.octree_nodes);
    if (i > 0) {
      EXPECT_GT(g.dims.x * g.dims.y, report.grids[i - 1].dims.x * report.grids[i - 1].dims.y);
      EXPECT_GT(g.input_bytes, report.grids[i - 1].input_bytes);
      EXPECT_GE(g.leaves, report.grids[i - 1].leaves);
    }
  }

  ASSERT_EQ(report.servers.size(), o.layouts.size());
  for (const auto& s : report.servers) {
    SCOPED_TRACE(s.layout.ranks * 10 + s.layout.threads);
    if (s.layout.ranks > 1 && o.mpirun.empty()) {
      EXPECT_FALSE(s.skipped.empty());
      continue;
    }
    EXPECT_TRUE(s.skipped.empty()) << s.skipped;
    EXPECT_EQ(s.complete, s.rounds);
    EXPECT_GT(s.cut, 0u);
    EXPECT_GT(s.cold_first.p50, 0);
    EXPECT_LE(s.cold_first.p50, s.cold_half.p50);
    EXPECT_LE(s.cold_half.p50, s.cold_all.p50);
    EXPECT_GT(s.scene_all.p50, 0);
  }

  ASSERT_EQ(report.subvolumes.size(), 4u);
  for (std::size_t i = 1; i < report.subvolumes.size(); ++i) {
    EXPECT_GE(report.subvolumes[i].cost.bricks, report.subvolumes[i - 1].cost.bricks);
    EXPECT_GE(report.subvolumes[i].cost.bytes_sent, report.subvolumes[i - 1].cost.bytes_sent);
  }
  // Eight sub-volumes name all four variables; one names only clw (plus ta to shade).
  EXPECT_EQ(report.subvolumes.back().cost.variables_read, 4u);

  const auto tables = bench::scaling_tables(report);
  ASSERT_EQ(tables.size(), 4u);
  EXPECT_EQ(tables[0].rows.size(), 3u);
  EXPECT_EQ(tables[2].rows.size(), o.layouts.size());
  EXPECT_EQ(tables[3].rows.size(), 4u);
  const auto j = bench::scaling_json(report, tables);
  EXPECT_EQ(j["suite"], "scaling");
  EXPECT_EQ(j["grids"].size(), 3u);
}

// An installed mpirun that cannot start jobs costs only its own layouts: they are marked
// skipped with the reason, and the threaded server is still measured.
TEST(ScalingSuiteQuickTest, MpirunThatCannotStartSkipsOnlyItsLayouts) {
  bench::ScalingSuiteOptions o = bench::quick_scaling_options({});
  o.work = std::filesystem::temp_directory_path() / "strielad_scaling_suite_broken_mpirun_test";
  o.server_binary = STRIELAD_SERVE_EXE;
  o.mpirun = "/bin/false";  // exits at once: the server never reports its port
  o.fractions = {1.0};
  o.layouts = {{1, 1}, {2, 1}};
  const auto report = bench::run_scaling_suite(o);
  ASSERT_EQ(report.servers.size(), 2u);
  EXPECT_TRUE(report.servers[0].skipped.empty()) << report.servers[0].skipped;
  EXPECT_EQ(report.servers[0].complete, report.servers[0].rounds);
  EXPECT_NE(report.servers[1].skipped.find("mpirun did not start the server"), std::string::npos)
      << report.servers[1].skipped;
  EXPECT_EQ(report.servers[1].complete, 0u);
}

}  // namespace
}  // namespace strielad::testing
