// SPDX-License-Identifier: Apache-2.0
// The latency benchmark runs end to end in quick mode against an in-process server: the
// fly-in's cut gets answered, every phase completes its cut, rapid time changes leave no
// stale result and end with a complete cut, concurrent clients see no error, and the
// report has every table, so the harness cannot rot between full runs.
#include <gtest/gtest.h>

#include <algorithm>

#include "bench/latency_suite.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

TEST(LatencySuiteQuick, RunsEveryPhaseToACompleteCut) {
  testing::TempDir dir;
  bench::LatencySuiteOptions o = bench::quick_latency_options({});
  o.work = dir.path();
  const bench::LatencySuiteReport r = bench::run_latency_suite(o);

  ASSERT_FALSE(r.fly_in.empty());
  EXPECT_GT(r.fly_in_max_cut, 0u);
  EXPECT_GE(r.fly_in_complete_after_stop_s, 0.0);
  EXPECT_EQ(r.fly_in.back().answered, r.fly_in.back().cut);

  ASSERT_EQ(r.phases.size(), 6u);
  for (const auto& p : r.phases) {
    ASSERT_EQ(p.rounds.size(), 1u) << p.phase;
    const auto& round = p.rounds.front();
    EXPECT_TRUE(round.complete) << p.phase << (p.prefetch ? " with" : " without") << " prefetch";
    EXPECT_GT(round.nodes, 0u);
    EXPECT_GE(round.first, 0.0);
    EXPECT_LE(round.first, round.p50);
    EXPECT_LE(round.p50, round.p90);
    EXPECT_LE(round.p90, round.all);
    // Every answer of a complete cut is kept, in time order, ending at the whole cut.
    EXPECT_EQ(round.arrivals.size(), round.nodes);
    EXPECT_TRUE(std::is_sorted(round.arrivals.begin(), round.arrivals.end()));
    EXPECT_EQ(round.arrivals.front(), round.first);
    EXPECT_EQ(round.arrivals.back(), round.all);
  }
  EXPECT_GT(r.bytes_per_node, 0.0);

  EXPECT_GT(r.rapid.generations, 3u);
  EXPECT_EQ(r.rapid.stale, 0u);
  EXPECT_TRUE(r.rapid.final_complete);
  EXPECT_LE(r.rapid.max_queued, static_cast<std::int64_t>(r.rapid.cut));

  EXPECT_EQ(r.concurrent.disconnects, 0u);
  EXPECT_EQ(r.concurrent.errors, 0u);
  EXPECT_EQ(r.concurrent.failed, 0u);
  EXPECT_EQ(r.concurrent.stale, 0u);
  EXPECT_GT(r.concurrent.results, 0u);

  const auto tables = bench::latency_report_tables(r);
  EXPECT_EQ(tables.size(), 7u);
  // Time changes with and without prefetching: foreground and whole view each.
  const auto paper = std::find_if(tables.begin(), tables.end(),
                                  [](const bench::Table& t) { return t.name == "paper_comparison"; });
  ASSERT_NE(paper, tables.end());
  EXPECT_EQ(paper->rows.size(), 4u);
  const auto json = bench::latency_report_json(r, tables);
  EXPECT_EQ(json["suite"], "latency");
  EXPECT_EQ(json["arrivals"].size(), r.phases.size());
  EXPECT_EQ(json["targets"].size(), r.targets.size());
}

}  // namespace
}  // namespace strielad
