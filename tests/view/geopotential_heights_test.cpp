// SPDX-License-Identifier: Apache-2.0
// Heights from a geopotential variable (view/height_placement.h, issue 27 item 4): on a
// pressure-level store with zg the viewer asks the server for zg as one more attribute
// and places every vertex at its value, node boxes are widened to zg's range from the
// store's index so they hold every placed vertex (the standard atmosphere's boxes do
// not), and without the store on this machine the standard atmosphere stays and says why.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "convert/converter.h"
#include "geo/standard_atmosphere.h"
#include "lod/camera.h"
#include "store/store.h"
#include "support/netcdf_fixture.h"
#include "support/temp_dir.h"
#include "view/height_placement.h"
#include "view/local_server.h"
#include "view/view_controller.h"
#include "view/view_link.h"

namespace strielad {
namespace {

using namespace std::chrono_literals;
using testing::NcAttr;

const std::vector<double> kLevels{1000, 850, 700, 500, 300, 200};  // hPa

// zg: the standard atmosphere's height of the level plus 600 m, plus up to 400 m that
// varies with longitude: a warm atmosphere, higher than the standard one everywhere.
double zg_value(double lon, double hpa) {
  return geo::standard_height_m(hpa * 100.0) + 600.0 + 400.0 * std::sin(lon);
}

std::filesystem::path write_pressure_store(const std::filesystem::path& dir) {
  testing::SimpleGrid g;
  g.lev = kLevels;
  g.lat = {45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55};
  g.lon = {5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15};
  std::vector<double> ta, zg;
  for (double p : g.lev) {
    for (double lat : g.lat) {
      for (double lon : g.lon) {
        // A cold column: ta <= 250 K inside an ellipse around 10 E, 50 N, at every level.
        const double r = std::hypot((lon - 10) / 3.5, (lat - 50) / 3.0);
        ta.push_back(240.0 + 20.0 * r + 0.001 * p);
        zg.push_back(zg_value(lon, p));
      }
    }
  }
  testing::NetcdfFixture()
      .grid(g)
      .variable("ta", NC_FLOAT, g.dims(), ta, {NcAttr::text_value("units", "K")})
      .variable("zg", NC_FLOAT, g.dims(), zg,
                {NcAttr::text_value("units", "m"),
                 NcAttr::text_value("standard_name", "geopotential_height")})
      .write(dir / "p.nc");
  build::ConvertOptions o;
  o.inputs = {dir / "p.nc"};
  o.store = dir / "store";
  o.brick = 4;
  o.threads = 2;
  build::convert(o);
  return o.store;
}

TEST(GeopotentialHeightsTest, PlacementComesFromZgAndItsNodeRangesFromTheIndex) {
  testing::TempDir dir;
  const auto store = Store::open(write_pressure_store(dir.path()));
  const auto heights = view::choose_height_placement(store->manifest(), store.get());
  ASSERT_EQ(heights.kind, view::HeightPlacement::Kind::kVariable) << heights.description;
  EXPECT_EQ(heights.variable, "zg");
  EXPECT_NE(heights.description.find("'zg'"), std::string::npos) << heights.description;
  ASSERT_EQ(heights.node_heights_m.size(), store->octree().node_count());
  // The root holds every height: the standard atmosphere's at 1000 hPa (the fallback
  // where zg would be missing) up to the highest zg, at 200 hPa.
  const auto& root = heights.node_heights_m[store->octree().root()];
  double highest = -INFINITY;
  for (int lon = 5; lon <= 15; ++lon) highest = std::max(highest, zg_value(lon, 200));
  EXPECT_LE(root[0], geo::standard_height_m(100000.0));
  EXPECT_NEAR(root[1], highest, 0.01);
}

TEST(GeopotentialHeightsTest, WithoutTheStoreTheStandardAtmosphereStaysAndSaysWhy) {
  testing::TempDir dir;
  const auto store = Store::open(write_pressure_store(dir.path()));
  const auto heights = view::choose_height_placement(store->manifest(), nullptr);
  EXPECT_EQ(heights.kind, view::HeightPlacement::Kind::kFrame);
  EXPECT_NE(heights.description.find("standard atmosphere"), std::string::npos);
  EXPECT_NE(heights.description.find("'zg'"), std::string::npos);
  EXPECT_NE(heights.description.find("--connect"), std::string::npos);
}

TEST(GeopotentialHeightsTest, MeshesArePlacedAtZgAndInsideTheirWidenedBoxes) {
  testing::TempDir dir;
  const auto path = write_pressure_store(dir.path());
  const auto store = Store::open(path);
  auto heights = view::choose_height_placement(store->manifest(), store.get());
  ASSERT_EQ(heights.kind, view::HeightPlacement::Kind::kVariable);
  auto connection = view::open_local_store(path, view::LocalServerOptions{.threads = 2});
  view::ViewLink link(std::move(connection.client), heights);
  Scene scene;
  SubVolume cold;
  cold.id = 1;
  cold.name = "cold column";
  cold.limits.push_back(Limit{.var = "ta", .min = std::nullopt, .max = 250.0});
  scene.subvolumes = {cold};
  scene.attributes = {"ta"};  // the link adds zg
  view::ViewController controller(link, scene, {.lod = {.split_solid_angle_sr = 1e-9},
                                                .vertical_exaggeration = 1.0});
  const auto& frame = controller.frame();
  const lod::Camera camera = lod::look_at({0, -3000, 10}, {0, 0, 5}, 45.0, 1.0, frame.domain());
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  while (!(controller.update(camera).cut_changes == 0 && controller.complete())) {
    ASSERT_FALSE(controller.connection_lost()) << controller.last_error().value_or("?");
    ASSERT_LT(std::chrono::steady_clock::now(), deadline);
    std::this_thread::sleep_for(1ms);
  }
  // Boxes of the standard atmosphere alone, to show that some vertices leave them.
  const auto standard = lod::node_world_boxes(link.octree(), frame);
  std::size_t vertices = 0, outside_standard = 0;
  for (const auto& [node, entry] : controller.meshes().entries()) {
    if (!entry.mesh) continue;
    const lod::WorldBox& box = controller.cut().box(node);
    for (std::size_t v = 0; v < entry.mesh->vertex_count(); ++v) {
      const float* p = &entry.mesh->vertices[v * view::kVertexFloats];
      const float zg = p[view::kVertexAttributes + 1];  // the attribute after "ta"
      ASSERT_TRUE(std::isfinite(zg));
      EXPECT_NEAR(p[2] * 1000.0, zg, 0.5) << "node " << node << " vertex " << v;
      const Vec3 world{p[0], p[1], p[2]};
      lod::WorldBox widened = box;
      for (int a = 0; a < 3; ++a) {
        widened.lo[a] -= 1e-6 * (1 + std::fabs(widened.lo[a]));
        widened.hi[a] += 1e-6 * (1 + std::fabs(widened.hi[a]));
      }
      ASSERT_TRUE(widened.contains(world)) << "node " << node << " vertex " << v;
      // More than a metre above or below the standard atmosphere's box.
      if (world[2] > standard[node].hi[2] + 1e-3 || world[2] < standard[node].lo[2] - 1e-3) {
        ++outside_standard;
      }
      // Normals are unit vectors.
      EXPECT_NEAR(std::hypot(p[3], p[4], p[5]), 1.0, 1e-4);
      ++vertices;
    }
  }
  EXPECT_GT(vertices, 100u);
  EXPECT_GT(outside_standard, 0u);
}

}  // namespace
}  // namespace strielad
