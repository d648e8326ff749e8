// SPDX-License-Identifier: Apache-2.0
// The soak benchmark runs in quick mode against an in-process server: normal clients keep
// getting whole cuts answered next to slow readers and tricklers, the server closes the
// tricklers, its slots stay within their limits, and the report has every table.
#include <gtest/gtest.h>

#include "bench/soak_suite.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

TEST(SoakSuiteQuick, NormalClientsAreServedNextToSlowReadersAndTricklers) {
  testing::TempDir dir;
  bench::SoakSuiteOptions o = bench::quick_soak_options({});
  o.work = dir.path();
  const bench::SoakSuiteReport r = bench::run_soak_suite(o);

  ASSERT_GE(r.samples.size(), 3u);
  for (const bench::SoakSample& s : r.samples) {
    EXPECT_TRUE(s.stats_answered) << "at " << s.t << " s";
    EXPECT_LE(s.clients, static_cast<std::int64_t>(o.max_clients));
    EXPECT_LE(s.handshakes, static_cast<std::int64_t>(o.max_handshakes));
  }
  ASSERT_EQ(r.kinds.size(), 3u);
  const auto& normal = r.kinds[0];
  EXPECT_GT(normal.rounds, 0u);
  EXPECT_EQ(normal.answers, normal.rounds * r.octree_nodes);
  EXPECT_EQ(normal.errors, 0u);
  EXPECT_EQ(normal.refused, 0u);
  EXPECT_GT(r.kinds[1].requests, 0u);
  EXPECT_EQ(r.kinds[1].refused, 0u);
  EXPECT_GT(r.kinds[2].closed_by_server, 0u);  // the handshake deadline or the pool's limit
  EXPECT_GT(r.rss_max, 0u);

  const auto tables = bench::soak_report_tables(r);
  ASSERT_EQ(tables.size(), 3u);
  EXPECT_EQ(tables[0].rows.size(), r.samples.size());
  EXPECT_EQ(bench::soak_report_json(r, tables)["suite"], "soak");
}

}  // namespace
}  // namespace strielad
