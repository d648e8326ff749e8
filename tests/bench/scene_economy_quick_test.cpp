// SPDX-License-Identifier: Apache-2.0
// The scene economy suite's harness in quick mode: every scene is measured for every
// view and both references, a view never costs more than the same scene at every leaf
// in bricks and bytes sent, no scene reads more than its own variables, and the whole
// step outweighs every scene.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

#include "bench/scene_economy.h"

namespace strielad::testing {
namespace {

TEST(SceneEconomyQuickTest, ViewsCostLessThanTheWholeStep) {
  bench::SceneEconomyOptions o = bench::quick_scene_economy_options({});
  o.work = std::filesystem::temp_directory_path() / "strielad_scene_economy_quick_test";
  const auto report = bench::run_scene_economy(o);
  ASSERT_EQ(report.scene_json.size(), 4u);
  ASSERT_EQ(report.costs.size(), 4u * 5u);
  std::map<std::string, const bench::SceneCost*> every, step;
  for (const auto& c : report.costs) {
    if (c.view == "every leaf") every[c.scene] = &c;
    if (c.view == "whole step") step[c.scene] = &c;
  }
  ASSERT_EQ(every.size(), 4u);
  ASSERT_EQ(step.size(), 4u);
  for (const auto& c : report.costs) {
    SCOPED_TRACE(c.scene + " / " + c.view);
    const auto& s = *step[c.scene];
    EXPECT_LE(c.bricks, s.bricks);
    EXPECT_GT(c.nodes, 0u);
    if (c.view == "whole step") {
      EXPECT_EQ(c.variables_read, o.variables.size());
      continue;
    }
    EXPECT_EQ(c.extracted + c.skipped <= c.nodes, true);
    // A scene reads at most its own variables: two for the limits plus an attribute.
    EXPECT_LE(c.variables_read, 2u);
    EXPECT_LT(c.bytes_read, s.bytes_read);
    if (c.view != "every leaf") {
      EXPECT_LE(c.bricks, every[c.scene]->bricks);
      EXPECT_LE(c.bytes_sent, every[c.scene]->bytes_sent);
    } else {
      EXPECT_GT(c.bytes_sent, 0u);
    }
  }
  const auto tables = bench::scene_economy_tables(report);
  ASSERT_EQ(tables.size(), 1u);
  EXPECT_EQ(tables[0].rows.size(), report.costs.size());
}

}  // namespace
}  // namespace strielad::testing
