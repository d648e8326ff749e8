// SPDX-License-Identifier: Apache-2.0
// Float64 variables are extracted in float32: values beyond +-3.4e38 are clamped, so they
// stay valid samples inside their limits and give finite attributes. They used to become
// +-Inf, which read as missing (an empty region) and as infinite attributes (which the
// server's mesh encoding refuses).
#include <gtest/gtest.h>

#include <cmath>

#include "convert/converter.h"
#include "extract/mesh_metrics.h"
#include "extract/node_extraction.h"
#include "protocol/mesh_encoding.h"
#include "scene/scene.h"
#include "store/store.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using namespace strielad::testing;

TEST(Float64BeyondFloat32Test, HugeValuesStayValidAndAttributesFinite) {
  TempDir dir;
  SimpleGrid g;  // 4 lon x 3 lat x 2 levels, one step
  std::vector<double> data(g.samples(), 1e300);
  data[0] = -1e300;
  NetcdfFixture().grid(g).variable("d", NC_DOUBLE, g.dims(), data).write(dir / "d.nc");
  build::ConvertOptions o;
  o.inputs = {dir / "d.nc"};
  o.store = dir / "store";
  o.brick = 4;
  o.threads = 1;
  build::convert(o);
  const auto store = Store::open(dir / "store");
  ASSERT_EQ(store->manifest().variables[0].dtype, DType::kFloat64);
  EXPECT_EQ(store->node_entry(0, 0, 0).max, 1e300);  // the index stays exact

  const ResolvedScene scene = resolve_scene(
      parse_scene(R"({"subvolumes": [{"id": 1, "limits": [{"var": "d", "min": 1}]},
                                     {"id": 2, "limits": [{"var": "d", "min": 1e300}]}],
                      "attributes": ["d"]})",
                  "scene"),
      store->manifest(), "scene");
  const NodeExtraction n = extract_node(*store, nullptr, scene, 0, store->octree().root());
  ASSERT_EQ(n.results.size(), 2u);
  const SubVolumeResult& r = n.results[0];
  ASSERT_EQ(r.outcome, NodeOutcome::kMesh);
  EXPECT_TRUE(check_mesh(r.mesh).clean());
  // Every sample but one is inside: most of the grid's box.
  const double box = (g.lon.back() - g.lon.front()) * (10.0 - -10.0) * (1000.0 - 850.0);
  EXPECT_GT(std::fabs(enclosed_volume(r.mesh)), 0.5 * box);
  for (float v : r.mesh.attributes.at(0)) {
    ASSERT_TRUE(std::isfinite(v));
    EXPECT_LE(std::fabs(v), std::numeric_limits<float>::max());
  }
  ByteWriter w;
  EXPECT_NO_THROW(protocol::encode_mesh(r.mesh, w));
  // A bound beyond the float range selects none of them (documented).
  EXPECT_EQ(n.results[1].outcome, NodeOutcome::kEmpty);
}

}  // namespace
}  // namespace strielad
