// SPDX-License-Identifier: Apache-2.0
// The viewer on terrain-following stores (view/height_placement.h, view/level_heights.h,
// view/model_surface_dem.h): an ICON-like store converted from the model-like sample is
// placed by its geometry field (vertices exactly, the frame by the centre column), every
// placed vertex of every node's meshes lies in the node's widened box, a cold sub-volume
// (temp <= T) sits on the ridge's ground where the plain has it at the isotherm, the
// sigma-pressure store's pressures become standard-atmosphere heights, the model's
// surface reads as a DEM (drawn on the globe too, placed as the meshes are), and without
// the store on this machine the viewer refuses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "convert/converter.h"
#include "extract/level_extraction.h"
#include "format/geometry_field.h"
#include "geo/standard_atmosphere.h"
#include "scene/scene.h"
#include "store/store.h"
#include "support/expect_error.h"
#include "support/temp_dir.h"
#include "synthetic/model_like_files.h"
#include "view/height_placement.h"
#include "view/model_surface_dem.h"
#include "view/node_geometry.h"
#include "view/terrain_tiles.h"
#include "lod/wgs84_globe.h"

namespace strielad {
namespace {

constexpr Dims3 kDims{40, 32, 14};

std::filesystem::path convert_model(const testing::TempDir& dir, synthetic::SampleModel model,
                                    std::size_t steps) {
  synthetic::SampleSpec spec;
  spec.dims = kDims;
  spec.steps = steps;
  spec.file_per_step = false;
  const auto input = synthetic::write_model_like_dataset(spec, model, dir / "in");
  build::ConvertOptions o;
  o.inputs = {input.files.front().path};
  o.store = dir / "store";
  o.brick = 8;
  o.threads = 2;
  build::convert(o);
  return o.store;
}

// A placed vertex's x, y, z (world km at exaggeration 1) and its geometry attribute.
struct PlacedVertex {
  Vec3 world;
  float attribute = 0;
};

// Every node of every level extracted with `scene` (its attributes end with the geometry
// field) and placed; `check(node, vertex)` sees each vertex.
template <typename Check>
std::size_t place_every_node(const Store& store, const Scene& scene,
                             const view::GeometryPlacer& placer, std::uint32_t step,
                             Check check) {
  const ResolvedScene resolved = resolve_scene(scene, store.manifest(), "test scene");
  const int height_attribute = static_cast<int>(scene.attributes.size()) - 1;
  std::size_t vertices = 0;
  for (std::uint32_t level = 0; level < store.octree().level_count(); ++level) {
    LevelExtractionOptions o;
    o.step = step;
    o.level = level;
    o.threads = 2;
    o.merge_face_squares = false;
    LevelExtraction extracted = extract_level(store, resolved, o);
    for (NodeExtraction& n : extracted.nodes) {
      protocol::NodeResult result;
      result.node = n.node;
      result.subvolumes = std::move(n.results);
      const auto geometry = placer.place(
          result, step, [](std::uint32_t id) { return id == 1 ? 0 : -1; }, height_attribute);
      for (std::size_t v = 0; v < geometry->vertex_count(); ++v) {
        const float* p = &geometry->vertices[v * view::kVertexFloats];
        check(n.node, PlacedVertex{{p[0], p[1], p[2]},
                                   p[view::kVertexAttributes + height_attribute]});
        ++vertices;
      }
    }
  }
  return vertices;
}

Scene cold_scene(const format::Manifest& m, const std::string& temperature, double t_max) {
  Scene scene;
  SubVolume cold;
  cold.id = 1;
  cold.name = "cold";
  cold.limits.push_back(Limit{.var = temperature, .min = std::nullopt, .max = t_max});
  scene.subvolumes = {cold};
  scene.attributes = {temperature, format::geometry_field_name(m)};
  return scene;
}

bool inside(const lod::WorldBox& box, const Vec3& p) {
  for (int a = 0; a < 3; ++a) {
    const double tol = 1e-5 * (1 + std::fabs(box.lo[a]) + std::fabs(box.hi[a]));
    if (p[a] < box.lo[a] - tol || p[a] > box.hi[a] + tol) return false;
  }
  return true;
}

TEST(TerrainFollowingViewTest, IconStoreIsPlacedByItsGeometryField) {
  const testing::TempDir dir;
  const auto store = Store::open(convert_model(dir, synthetic::SampleModel::kIcon, 1));
  const format::Manifest& m = store->manifest();
  const auto heights = view::choose_height_placement(m, store.get());
  ASSERT_EQ(heights.kind, view::HeightPlacement::Kind::kVariable) << heights.description;
  EXPECT_EQ(heights.variable, "geometry_height");
  EXPECT_NE(heights.description.find("terrain-following"), std::string::npos);
  ASSERT_EQ(heights.level_heights_m.size(), kDims.z);
  // ICON counts levels from the top: the centre column's heights fall with the index.
  for (std::size_t k = 1; k < kDims.z; ++k) {
    EXPECT_LT(heights.level_heights_m[k], heights.level_heights_m[k - 1]) << k;
  }
  const view::GeometryPlacer placer(m, heights);
  EXPECT_EQ(placer.frame().vertical(), lod::VerticalMap::kLevelHeights);
  EXPECT_TRUE(placer.frame().mirrored());
  for (std::size_t k = 0; k < kDims.z; ++k) {
    EXPECT_DOUBLE_EQ(placer.frame().sample_world_z(k), heights.level_heights_m[k] * 1e-3);
  }
}

TEST(TerrainFollowingViewTest, EveryPlacedVertexIsInItsNodesBoxAndTheColdAirSitsOnTheRidge) {
  const testing::TempDir dir;
  const auto store = Store::open(convert_model(dir, synthetic::SampleModel::kIcon, 1));
  const format::Manifest& m = store->manifest();
  const auto heights = view::choose_height_placement(m, store.get());
  ASSERT_EQ(heights.kind, view::HeightPlacement::Kind::kVariable);
  const view::GeometryPlacer placer(m, heights);
  auto boxes = lod::node_world_boxes(store->octree(), placer.frame());
  const auto frame_boxes = boxes;
  heights.widen_boxes(boxes, 1.0);

  // Colder than the standard atmosphere at 1500 m: the air above a roughly level
  // isotherm, down to the ground where the ground is higher.
  const double t_max = 288.15 - 0.0065 * 1500.0;
  const auto surface = store->horizontal_coordinates();
  ASSERT_TRUE(surface && surface->surface_m);
  const std::vector<double>& ground = *surface->surface_m;
  std::vector<double> lowest(kDims.x * kDims.y, INFINITY);
  const double x0 = m.x.values.front(), dx = m.x.values[1] - m.x.values[0];
  const double y0 = m.y.values.front(), dy = m.y.values[1] - m.y.values[0];
  std::size_t outside_frame_boxes = 0;
  const std::size_t vertices = place_every_node(
      *store, cold_scene(m, "temp", t_max), placer, 0,
      [&](NodeId node, const PlacedVertex& v) {
        ASSERT_TRUE(std::isfinite(v.attribute));
        EXPECT_NEAR(v.world[2] * 1000.0, v.attribute, 0.05);
        ASSERT_TRUE(inside(boxes[node], v.world))
            << "node " << node << " vertex at " << v.world[0] << " " << v.world[1] << " "
            << v.world[2] << " box z " << boxes[node].lo[2] << " " << boxes[node].hi[2];
        outside_frame_boxes += !inside(frame_boxes[node], v.world);
        if (store->octree().key(node).level != 0) return;
        // Vertices on a column of samples (on vertical lattice edges and grid faces).
        const Vec3 axis = placer.frame().to_axis(v.world);
        const double fi = (axis[0] - x0) / dx, fj = (axis[1] - y0) / dy;
        if (std::fabs(fi - std::round(fi)) > 1e-3 || std::fabs(fj - std::round(fj)) > 1e-3) return;
        const auto i = static_cast<std::size_t>(std::lround(fi));
        const auto j = static_cast<std::size_t>(std::lround(fj));
        ASSERT_LT(i, kDims.x);
        ASSERT_LT(j, kDims.y);
        double& low = lowest[j * kDims.x + i];
        low = std::min(low, v.world[2] * 1000.0);
      });
  ASSERT_GT(vertices, 0u);
  // The frame's centre column alone would leave vertices out of their boxes.
  EXPECT_GT(outside_frame_boxes, 0u);

  // Ridge: the highest tenth of the columns; plain: the lowest tenth.
  std::vector<double> sorted = ground;
  std::sort(sorted.begin(), sorted.end());
  const double ridge_from = sorted[sorted.size() * 9 / 10], plain_to = sorted[sorted.size() / 10];
  ASSERT_GT(ridge_from - plain_to, 1000.0) << "the sample domain has no ridge";
  double ridge_sum = 0, plain_sum = 0;
  std::size_t ridge_n = 0, plain_n = 0;
  for (std::size_t c = 0; c < ground.size(); ++c) {
    if (!std::isfinite(lowest[c])) continue;
    // Nothing of the cold air below the ground.
    EXPECT_GE(lowest[c], ground[c] - 1.0) << "column " << c;
    if (ground[c] >= ridge_from) {
      ridge_sum += lowest[c];
      ++ridge_n;
    } else if (ground[c] <= plain_to) {
      plain_sum += lowest[c];
      ++plain_n;
    }
  }
  ASSERT_GT(ridge_n, 0u);
  ASSERT_GT(plain_n, 0u);
  EXPECT_GT(ridge_sum / ridge_n, plain_sum / plain_n + 500.0)
      << "ridge " << ridge_sum / ridge_n << " m, plain " << plain_sum / plain_n << " m";
}

TEST(TerrainFollowingViewTest, SigmaPressureFieldBecomesStandardAtmosphereHeights) {
  const testing::TempDir dir;
  const auto store = Store::open(convert_model(dir, synthetic::SampleModel::kSigmaPressure, 2));
  const format::Manifest& m = store->manifest();
  const auto heights = view::choose_height_placement(m, store.get());
  ASSERT_EQ(heights.kind, view::HeightPlacement::Kind::kVariable);
  EXPECT_EQ(heights.variable, "geometry_pressure");
  EXPECT_GT(heights.pascals_per_unit, 0);
  EXPECT_NEAR(heights.metres(50000.0), geo::standard_height_m(50000.0), 1e-9);
  // The root's heights: the standard atmosphere's of the highest and lowest pressures
  // over both steps.
  const auto v = *format::geometry_field_variable(m);
  double p_lo = INFINITY, p_hi = -INFINITY;
  for (std::uint32_t step = 0; step < 2; ++step) {
    const auto& e = store->node_entry(step, v, store->octree().root());
    p_lo = std::min(p_lo, e.min);
    p_hi = std::max(p_hi, e.max);
  }
  const auto& root = heights.node_heights_m[store->octree().root()];
  EXPECT_NEAR(root[0], geo::standard_height_m(p_hi), 1e-6);
  EXPECT_NEAR(root[1], geo::standard_height_m(p_lo), 1e-6);
  const view::GeometryPlacer placer(m, heights);
  auto boxes = lod::node_world_boxes(store->octree(), placer.frame());
  heights.widen_boxes(boxes, 1.0);
  const double t_max = 288.15 - 0.0065 * 1500.0;
  for (std::uint32_t step = 0; step < 2; ++step) {
    const std::size_t n = place_every_node(
        *store, cold_scene(m, "t", t_max), placer, step, [&](NodeId node, const PlacedVertex& p) {
          EXPECT_NEAR(p.world[2] * 1000.0, geo::standard_height_m(p.attribute), 0.05);
          ASSERT_TRUE(inside(boxes[node], p.world)) << "node " << node << " step " << step;
        });
    EXPECT_GT(n, 0u);
  }
}

TEST(TerrainFollowingViewTest, TheModelSurfaceIsADem) {
  const testing::TempDir dir;
  const auto store = Store::open(convert_model(dir, synthetic::SampleModel::kIcon, 1));
  const format::Manifest& m = store->manifest();
  const auto heights = view::choose_height_placement(m, store.get());
  const view::GeometryPlacer placer(m, heights);
  const view::ModelSurfaceDem dem(m, placer.frame(), store->horizontal_coordinates(), "icon");
  EXPECT_EQ(dem.width(), kDims.x);
  EXPECT_EQ(dem.height(), kDims.y);
  const auto corner = dem.georeference(3.0, 5.0);
  EXPECT_NEAR(corner.lon, m.x.values[3], 1e-9);
  EXPECT_NEAR(corner.lat, m.y.values[5], 1e-9);
  const auto w = dem.read(geo::DemWindow{.col0 = 2, .row0 = 1, .cols = 3, .rows = 2, .stride = 4});
  ASSERT_EQ(w.size(), 6u);
  const auto& s = *store->horizontal_coordinates()->surface_m;
  EXPECT_EQ(w[4], static_cast<float>(s[(1 + 4) * kDims.x + 2 + 4]));
}

// On the globe the model's surface is placed as the meshes are: ECEF at the globe's
// exaggeration, each sample at its own longitude, latitude and surface height.
TEST(TerrainFollowingViewTest, TheModelSurfaceIsDrawnOnTheGlobe) {
  const testing::TempDir dir;
  const auto store = Store::open(convert_model(dir, synthetic::SampleModel::kIcon, 1));
  const format::Manifest& m = store->manifest();
  constexpr double kExaggeration = 20.0;
  const view::GeometryPlacer placer(
      m, view::choose_height_placement(m, store.get()), nullptr,
      view::PlacerShape{.shape = lod::FrameShape::kGlobe, .globe_exaggeration = kExaggeration});
  const lod::WorldFrame& frame = placer.frame();
  ASSERT_TRUE(frame.globe());
  auto dem = std::make_shared<const view::ModelSurfaceDem>(m, frame, store->horizontal_coordinates(),
                                                           "icon");
  const auto corner = dem->georeference(3.0, 5.0);
  EXPECT_NEAR(corner.lon, m.x.values[3], 1e-9);
  EXPECT_NEAR(corner.lat, m.y.values[5], 1e-9);
  const view::TerrainTiles tiles(dem, frame);
  const auto tile = tiles.load_tile({0, 0, 0});
  const auto samples = tiles.samples({0, 0, 0});
  const auto& surface = *store->horizontal_coordinates()->surface_m;
  const auto [lo, hi] = std::minmax_element(surface.begin(), surface.end());
  ASSERT_GT(*hi, 100.0);  // a ridge to see
  // The tile's vertices, row by row over its samples: each at its sample's place.
  ASSERT_EQ(tile->vertices.size(),
            samples.cols.size() * samples.rows.size() * view::kTerrainVertexFloats);
  std::size_t k = 0;
  for (const std::size_t row : samples.rows) {
    for (const std::size_t col : samples.cols) {
      const float* v = &tile->vertices[k++ * view::kTerrainVertexFloats];
      const double h = std::max(surface[row * kDims.x + col], 0.0);  // water lies at sea level
      const Vec3 expected = lod::geodetic_to_ecef_km(m.x.values[col], m.y.values[row],
                                                     h * 1e-3 * kExaggeration);
      for (int a = 0; a < 3; ++a) {
        ASSERT_NEAR(v[a], expected[a], 2e-3) << "column " << col << " row " << row;
      }
    }
  }
}

TEST(TerrainFollowingViewTest, WithoutTheStoreOnThisMachineTheViewerRefuses) {
  const testing::TempDir dir;
  const auto store = Store::open(convert_model(dir, synthetic::SampleModel::kIcon, 1));
  testing::expect_error([&] { view::choose_height_placement(store->manifest(), nullptr); },
                        ErrorCode::kUnsupported,
                        {"terrain-following", "geometry_height", "own machine"});
  // A curvilinear horizontal geometry is placed by its GEOMETRY coordinates, which only
  // the store's files give: without them its frame is refused by name.
  format::Manifest curvilinear = store->manifest();
  curvilinear.geometry->horizontal.kind = format::HorizontalGeometry::Kind::kCurvilinear;
  curvilinear.geometry->horizontal.lon_variable = "clon";
  curvilinear.geometry->horizontal.lat_variable = "clat";
  const view::HeightPlacement heights = view::choose_height_placement(curvilinear, store.get());
  testing::expect_error([&] { view::GeometryPlacer placer(curvilinear, heights); },
                        ErrorCode::kUnsupported, {"curvilinear grid ('clon' / 'clat')", "GEOMETRY"});
}

}  // namespace
}  // namespace strielad
