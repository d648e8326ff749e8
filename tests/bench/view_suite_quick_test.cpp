// SPDX-License-Identifier: Apache-2.0
// The view benchmark runs end to end in quick mode (a tiny store, a tiny image, one
// repeat) on the headless renderer: cut updates are timed on the paper's octree, every
// view renders complete with the LOD cut and with every leaf, the A-buffer saw
// fragments, time-step changes complete, and the report has every table, so the
// harness cannot rot between full runs.
#include <gtest/gtest.h>

#include "bench/view_bench.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

TEST(ViewSuiteQuick, MeasuresEveryPartOfTheView) {
  testing::TempDir dir;
  bench::ViewSuiteOptions o = bench::quick_view_options({});
  o.work = dir.path();
  o.repeat = 1;
  const bench::ViewSuiteReport r = bench::run_view_suite(o);

  EXPECT_FALSE(r.gl.empty());
  EXPECT_EQ(r.cut.octree_nodes, 51393u);  // the paper's octree
  EXPECT_EQ(r.cut.micros.count, r.cut.updates_per_pass);
  EXPECT_GT(r.cut.micros.min, 0.0);
  EXPECT_LE(r.cut.micros.median, r.cut.micros.max);
  EXPECT_GT(r.cut.min_nodes, 0u);
  EXPECT_FALSE(r.cut.segments.empty());

  const std::size_t views = 1 + o.fly_in_keyframes.size();
  ASSERT_EQ(r.frames.size(), 2 * views);
  for (std::size_t i = 0; i < r.frames.size(); i += 2) {
    const auto& lod = r.frames[i];
    const auto& full = r.frames[i + 1];
    SCOPED_TRACE(lod.view);
    ASSERT_FALSE(lod.full);
    ASSERT_TRUE(full.full);
    EXPECT_EQ(lod.view, full.view);
    EXPECT_GT(lod.cut_nodes, 0u);
    EXPECT_GE(full.cut_nodes, lod.cut_nodes);
    EXPECT_LE(full.cut_nodes, r.store_leaves);
    EXPECT_GT(lod.triangles, 0u);
    EXPECT_GE(full.triangles, lod.triangles);
    for (const auto* f : {&lod, &full}) {
      EXPECT_EQ(f->render_ms.count, 1u);
      EXPECT_GT(f->render_ms.median, 0.0);
      EXPECT_GT(f->stats.fragments_per_covered_pixel(), 0.0);
      EXPECT_GT(f->stats.max_fragments_per_pixel, 0u);
    }
  }

  ASSERT_EQ(r.time_changes.size(), views);
  for (const auto& c : r.time_changes) {
    SCOPED_TRACE(c.view);
    EXPECT_EQ(c.changes, 1);
    EXPECT_EQ(c.completed, 1);
    EXPECT_GE(c.first_ms.median, 0.0);
    EXPECT_LE(c.first_ms.median, c.complete_ms.median);
    EXPECT_LE(c.complete_ms.median, c.picture_ms.median);
  }

  const auto tables = bench::view_report_tables(r);
  EXPECT_EQ(tables.size(), 5u);
  const auto json = bench::view_report_json(r, tables);
  EXPECT_EQ(json["suite"], "view");
  EXPECT_EQ(json["targets"].size(), r.targets.size());
  EXPECT_TRUE(json["tables"].contains("frame_time"));
}

}  // namespace
}  // namespace strielad
