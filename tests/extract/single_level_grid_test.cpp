// SPDX-License-Identifier: Apache-2.0
// A store with one vertical level has no cells: extraction gives empty (or skipped)
// results without reading bricks, instead of failing every node with "extraction needs at
// least 2 samples along axis 2" as it used to.
#include <gtest/gtest.h>

#include "convert/converter.h"
#include "extract/node_extraction.h"
#include "scene/scene.h"
#include "store/store.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using namespace strielad::testing;

TEST(SingleLevelGridTest, EveryNodeIsEmptyOrSkipped) {
  TempDir dir;
  SimpleGrid g;
  g.lev = {850.0};
  g.lon = {0, 10, 20, 30, 40, 50, 60, 70, 80};
  NetcdfFixture().grid(g).variable("T", NC_FLOAT, g.dims(), ramp(g.samples())).write(dir / "t.nc");
  build::ConvertOptions o;
  o.inputs = {dir / "t.nc"};
  o.store = dir / "store";
  o.brick = 4;
  o.threads = 1;
  build::convert(o);
  const auto store = Store::open(dir / "store");
  const ResolvedScene scene = resolve_scene(
      parse_scene(R"({"subvolumes": [{"id": 1, "limits": [{"var": "T", "min": 3}]},
                                     {"id": 2, "domain": {"lon": [5, 25]}}],
                      "attributes": ["T"]})",
                  "scene"),
      store->manifest(), "scene");
  for (NodeId n = 0; n < store->octree().node_count(); ++n) {
    const NodeExtraction e = extract_node(*store, nullptr, scene, 0, n);
    EXPECT_EQ(e.bricks_used, 0u) << "node " << n;
    EXPECT_TRUE(node_brick_variables(*store, scene, 0, n).empty()) << "node " << n;
    for (const auto& r : e.results) {
      EXPECT_TRUE(r.outcome == NodeOutcome::kEmpty || r.outcome == NodeOutcome::kSkippedDomain ||
                  r.outcome == NodeOutcome::kSkippedValueRange)
          << "node " << n << ": " << node_outcome_name(r.outcome);
      EXPECT_TRUE(r.mesh.empty());
    }
  }
}

}  // namespace
}  // namespace strielad
