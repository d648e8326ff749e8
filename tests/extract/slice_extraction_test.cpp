// SPDX-License-Identifier: Apache-2.0
// Slices per node (lib/extract/slice_extraction.h, formats/scene.md "Slices"): values equal
// the data at samples and the trilinear field between them, planes sit exactly on their
// coordinate, neighbouring nodes' slices cover the plane once without cracks, iso-levels
// agree with a direct evaluation, and skips read no brick.
#include "extract/slice_extraction.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>

#include "convert/converter.h"
#include "extract/node_extraction.h"
#include "store/brick_cache.h"
#include "store/store.h"
#include "support/sphere_store.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

using testing::TempDir;

double test_field(double x, double y, double z) { return 3 * x - 2 * y + 0.5 * z + x * y * z; }

// 4 x 3 x 5 samples; x ascending non-uniform, y descending, z ascending.
NodeSamples lattice() {
  NodeSamples ns;
  ns.coords[0] = {0.0, 1.0, 3.0, 3.5};
  ns.coords[1] = {10.0, 8.0, 5.0};
  ns.coords[2] = {100.0, 200.0, 250.0, 400.0, 1000.0};
  const auto d = ns.dims();
  std::vector<float> f(ns.sample_count()), g(ns.sample_count());
  for (std::size_t z = 0; z < d[2]; ++z)
    for (std::size_t y = 0; y < d[1]; ++y)
      for (std::size_t x = 0; x < d[0]; ++x) {
        const std::size_t i = (z * d[1] + y) * d[0] + x;
        f[i] = static_cast<float>(test_field(double(x), double(y), double(z)));
        g[i] = static_cast<float>(1000.0 - 10.0 * double(z) + double(x));  // "pressure"
      }
  ns.fields = {f, g};
  return ns;
}

std::array<double, 3> face_normal(const Mesh& m, std::size_t t) {
  const auto& a = m.positions[m.triangles[t][0]];
  const auto& b = m.positions[m.triangles[t][1]];
  const auto& c = m.positions[m.triangles[t][2]];
  const std::array<double, 3> u{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const std::array<double, 3> v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

TEST(SliceExtractionTest, PlaneThroughSamplesReturnsTheSamplesExactly) {
  const NodeSamples ns = lattice();
  SliceRequest rq{.slice_id = 7, .axis = 2, .value = 250.0, .colour_field = 0, .colour_name = "f"};
  const Mesh m = extract_slice_mesh(ns, rq);
  ASSERT_EQ(m.vertex_count(), 4u * 3u);
  ASSERT_EQ(m.triangle_count(), 2u * 3u * 2u);
  EXPECT_EQ(m.subvolume_id, 7u);
  EXPECT_EQ(m.attribute_names, (std::vector<std::string>{"f"}));
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    const auto& p = m.positions[v];
    EXPECT_EQ(p[2], 250.0);
    const auto x = static_cast<std::size_t>(
        std::find(ns.coords[0].begin(), ns.coords[0].end(), p[0]) - ns.coords[0].begin());
    const auto y = static_cast<std::size_t>(
        std::find(ns.coords[1].begin(), ns.coords[1].end(), p[1]) - ns.coords[1].begin());
    ASSERT_LT(x, 4u);
    ASSERT_LT(y, 3u);
    EXPECT_EQ(m.attributes[0][v], ns.fields[0][(2 * 3 + y) * 4 + x]);  // bit for bit
    EXPECT_EQ(m.normals[v], (std::array<float, 3>{0, 0, 1}));
  }
  for (const FaceKind k : m.face_kinds) EXPECT_EQ(k, FaceKind::kSlice);
}

TEST(SliceExtractionTest, PlaneBetweenSamplesIsTheTrilinearField) {
  const NodeSamples ns = lattice();
  // x = 2.0: halfway between samples 1 (x = 1) and 2 (x = 3).
  const Mesh m = extract_slice_mesh(ns, SliceRequest{.slice_id = 1, .axis = 0, .value = 2.0});
  ASSERT_EQ(m.vertex_count(), 3u * 5u);
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    const auto& p = m.positions[v];
    EXPECT_EQ(p[0], 2.0);
    const auto y = static_cast<std::size_t>(
        std::find(ns.coords[1].begin(), ns.coords[1].end(), p[1]) - ns.coords[1].begin());
    const auto z = static_cast<std::size_t>(
        std::find(ns.coords[2].begin(), ns.coords[2].end(), p[2]) - ns.coords[2].begin());
    const double expected = 0.5 * ns.fields[0][(z * 3 + y) * 4 + 1] + 0.5 * ns.fields[0][(z * 3 + y) * 4 + 2];
    EXPECT_NEAR(m.attributes[0][v], expected, 1e-5 * std::max(1.0, std::abs(expected)));
  }
}

TEST(SliceExtractionTest, TrianglesFaceThePositiveAxisOnDescendingAxes) {
  const NodeSamples ns = lattice();  // y descends
  for (int axis = 0; axis < 3; ++axis) {
    SCOPED_TRACE(axis);
    const double value = ns.coords[axis][1];
    const Mesh m = extract_slice_mesh(ns, SliceRequest{.slice_id = 1, .axis = axis, .value = value});
    ASSERT_FALSE(m.empty());
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
      const auto n = face_normal(m, t);
      EXPECT_GT(n[axis], 0);
      EXPECT_EQ(n[(axis + 1) % 3], 0);
      EXPECT_EQ(n[(axis + 2) % 3], 0);
    }
  }
}

TEST(SliceExtractionTest, MissingSampleIsNaNOnlyWhereItContributes) {
  NodeSamples ns = lattice();
  ns.fields[0][(1 * 3 + 1) * 4 + 1] = std::numeric_limits<float>::quiet_NaN();  // z index 1
  // On the plane z = 200 (sample plane 1) only that vertex is missing.
  Mesh m = extract_slice_mesh(ns, SliceRequest{.slice_id = 1, .axis = 2, .value = 200.0});
  int missing = 0;
  for (float v : m.attributes[0]) missing += std::isnan(v) ? 1 : 0;
  EXPECT_EQ(missing, 1);
  // On z = 150 (between planes 0 and 1) the vertex above it is missing too, no other.
  m = extract_slice_mesh(ns, SliceRequest{.slice_id = 1, .axis = 2, .value = 150.0});
  missing = 0;
  for (float v : m.attributes[0]) missing += std::isnan(v) ? 1 : 0;
  EXPECT_EQ(missing, 1);
  // On z = 250 (plane 2) none.
  m = extract_slice_mesh(ns, SliceRequest{.slice_id = 1, .axis = 2, .value = 250.0});
  for (float v : m.attributes[0]) EXPECT_FALSE(std::isnan(v));
}

TEST(SliceExtractionTest, LevelSliceLiesOnTheIsoLevel) {
  const NodeSamples ns = lattice();
  // Field 1 = 1000 - 10 z + x (lattice units): linear, so the kernel's surface is the
  // exact level set; coloured by field 0.
  const Mesh m = extract_slice_mesh(
      ns, SliceRequest{.slice_id = 3, .axis = -1, .level_field = 1, .value = 985.0, .colour_field = 0});
  ASSERT_FALSE(m.empty());
  for (const FaceKind k : m.face_kinds) EXPECT_EQ(k, FaceKind::kSlice);
  for (std::size_t v = 0; v < m.vertex_count(); ++v) {
    std::array<double, 3> lattice_point{};
    for (int a = 0; a < 3; ++a) {
      // Invert the axis map (piecewise linear) to lattice coordinates.
      const auto& c = ns.coords[a];
      const double p = m.positions[v][a];
      for (std::size_t i = 0; i + 1 < c.size(); ++i) {
        const double lo = std::min(c[i], c[i + 1]), hi = std::max(c[i], c[i + 1]);
        if (p >= lo && p <= hi) {
          lattice_point[a] = double(i) + (p - c[i]) / (c[i + 1] - c[i]);
          break;
        }
      }
    }
    const double level = 1000 - 10 * lattice_point[2] + lattice_point[0];
    EXPECT_NEAR(level, 985.0, 1e-9);
    // The colour is the trilinear field 0 at that point.
    EXPECT_NEAR(m.attributes[0][v], field_at_lattice(ns, 0, lattice_point), 1e-4);
    // The normal points to decreasing values of field 1: up in z (z ascends).
    EXPECT_GT(m.normals[v][2], 0.0f);
  }
}

// The sphere store (33^3 samples, bricks of 8: 4 x 4 x 4 level-0 nodes).
class SliceStoreTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir();
    store_ = Store::open(testing::write_sphere_store(dir_->path()));
  }
  static void TearDownTestSuite() {
    store_.reset();
    delete dir_;
  }
  static ResolvedScene scene_with(const Slice& slice) {
    Scene s;
    s.subvolumes = {SubVolume{.id = 1, .name = "", .limits = {Limit{"d1", std::nullopt, 1.0}}, .domain = {}}};
    s.slices = {slice};
    return resolve_scene(s, store_->manifest(), "test");
  }
  static std::vector<NodeId> level_nodes(std::uint32_t level) {
    std::vector<NodeId> nodes;
    for (NodeId n = 0; n < store_->octree().node_count(); ++n) {
      if (store_->octree().key(n).level == level) nodes.push_back(n);
    }
    return nodes;
  }
  static inline TempDir* dir_ = nullptr;
  static inline std::shared_ptr<const Store> store_;
};

double area_in(const Mesh& m, int u, int w) {
  double area = 0;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const auto& a = m.positions[m.triangles[t][0]];
    const auto& b = m.positions[m.triangles[t][1]];
    const auto& c = m.positions[m.triangles[t][2]];
    area += 0.5 * std::abs((b[u] - a[u]) * (c[w] - a[w]) - (c[u] - a[u]) * (b[w] - a[w]));
  }
  return area;
}

TEST_F(SliceStoreTest, NeighbouringNodesCoverThePlaneOnceWithoutCracks) {
  // lat = -0.25 is a node face at level 0 (sample 8 of 33), lat = 0.1 is inside nodes.
  for (double lat : {-0.25, 0.1, 0.5}) {
    SCOPED_TRACE(lat);
    const ResolvedScene scene = scene_with(Slice{.id = 9, .axis = "lat", .value = lat, .var = "d2"});
    double area = 0;
    std::map<std::array<double, 3>, float> shared;  // position -> value, across nodes
    std::size_t meshes = 0, coinciding = 0;
    for (NodeId node : level_nodes(0)) {
      const NodeExtraction e = extract_node(*store_, nullptr, scene, 0, node);
      ASSERT_EQ(e.slices.size(), 1u);
      const SliceResult& r = e.slices[0];
      if (r.outcome != NodeOutcome::kMesh) {
        EXPECT_EQ(r.outcome, NodeOutcome::kSkippedDomain) << r.reason;
        continue;
      }
      ++meshes;
      area += area_in(r.mesh, 0, 2);
      for (std::size_t v = 0; v < r.mesh.vertex_count(); ++v) {
        EXPECT_EQ(r.mesh.positions[v][1], lat);
        const auto [it, fresh] = shared.emplace(r.mesh.positions[v], r.mesh.attributes[0][v]);
        if (!fresh) {
          ++coinciding;
          EXPECT_EQ(it->second, r.mesh.attributes[0][v]);  // the same value bit for bit
        }
      }
    }
    EXPECT_EQ(meshes, 16u);  // one row of 4 x 4 nodes, each once
    const auto& m = store_->manifest();
    const double full = (m.x.values.back() - m.x.values.front()) * (m.z.values.back() - m.z.values.front());
    EXPECT_NEAR(area, full, 1e-9 * full);  // no gap, no overlap
    EXPECT_GT(coinciding, 0u);             // neighbours share their boundary vertices
  }
}

TEST_F(SliceStoreTest, SkipsReadNoBrick) {
  // A level-0 node at the southern edge: lat -0.5 .. -0.25.
  NodeId node = 0;
  for (NodeId n : level_nodes(0)) {
    if (node_geometry(*store_, n).coords[1].front() == -0.5) node = n;
  }
  ASSERT_EQ(node_geometry(*store_, node).coords[1].back(), -0.25);
  const auto before = store_->counters();
  BrickCache cache(64 << 20);
  {
    const ResolvedScene scene = scene_with(Slice{.id = 2, .axis = "lat", .value = 0.3, .var = "d2"});
    // Only the slice: drop the sub-volume so nothing else could read.
    ResolvedScene only = scene;
    only.subvolumes.clear();
    const NodeExtraction e = extract_node(*store_, &cache, only, 0, node);
    EXPECT_EQ(e.slices[0].outcome, NodeOutcome::kSkippedDomain);
    EXPECT_NE(e.slices[0].reason.find("misses the node"), std::string::npos) << e.slices[0].reason;
    EXPECT_EQ(e.bricks_used, 0u);
    EXPECT_TRUE(node_brick_variables(*store_, only, 0, node).empty());
  }
  {
    ResolvedScene only = scene_with(Slice{.id = 2, .axis = "lat", .value = -0.25, .var = "d2"});
    only.subvolumes.clear();
    const NodeExtraction e = extract_node(*store_, &cache, only, 0, node);
    EXPECT_EQ(e.slices[0].outcome, NodeOutcome::kSkippedDomain);
    EXPECT_NE(e.slices[0].reason.find("neighbouring node draws"), std::string::npos);
  }
  {
    ResolvedScene only = scene_with(Slice{.id = 2, .level_var = "d1", .value = 1e6, .var = "d2"});
    only.subvolumes.clear();
    const NodeExtraction e = extract_node(*store_, &cache, only, 0, node);
    EXPECT_EQ(e.slices[0].outcome, NodeOutcome::kSkippedValueRange);
    EXPECT_NE(e.slices[0].reason.find("never equals"), std::string::npos);
  }
  EXPECT_EQ(store_->counters().chunks_read, before.chunks_read);
}

TEST_F(SliceStoreTest, LevelSliceMatchesTheSubVolumeSurface) {
  // The iso-level d1 = 20 and the sub-volume d1 <= 20 share their surface: every slice
  // vertex is a vertex of the sub-volume's limit faces, and carries d1 close to 20.
  Scene s;
  s.subvolumes = {SubVolume{.id = 1, .name = "", .limits = {Limit{"d1", std::nullopt, 20.0}}, .domain = {}}};
  s.slices = {Slice{.id = 4, .level_var = "d1", .value = 20.0, .var = "d1"}};
  // The region {d1 >= 20} and {d1 <= 20} share the iso-surface.
  const ResolvedScene scene = resolve_scene(s, store_->manifest(), "test");
  std::size_t slice_vertices = 0;
  for (NodeId node : level_nodes(0)) {
    const NodeExtraction e = extract_node(*store_, nullptr, scene, 0, node);
    const SliceResult& r = e.slices[0];
    if (r.outcome != NodeOutcome::kMesh) continue;
    std::map<std::array<double, 3>, int> surface;
    const Mesh& sv = e.results[0].mesh;
    for (std::size_t t = 0; t < sv.triangle_count(); ++t) {
      if (sv.face_kinds[t] != FaceKind::kLimit) continue;
      for (auto v : sv.triangles[t]) surface[sv.positions[v]] = 1;
    }
    for (std::size_t v = 0; v < r.mesh.vertex_count(); ++v) {
      ++slice_vertices;
      EXPECT_TRUE(surface.contains(r.mesh.positions[v]));
      EXPECT_NEAR(r.mesh.attributes[0][v], 20.0, 0.5);
    }
  }
  EXPECT_GT(slice_vertices, 100u);
}

// A real file: cdf/contour.cdf (libncarg-data) has a pressure z axis in millibars; the
// 500 hPa plane is a sample plane, so its values are the file's.
TEST(SliceRealFileTest, PressurePlaneOfContourCdfReturnsItsSamples) {
  const auto file = testing::ncarg_file("cdf/contour.cdf");
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "libncarg-data is not installed";
  TempDir dir;
  build::ConvertOptions o;
  o.inputs = {file};
  o.store = dir.path() / "contour";
  o.threads = 2;
  build::convert(o);
  const auto store = Store::open(o.store);
  Scene s;
  s.subvolumes = {SubVolume{.id = 1, .name = "", .limits = {Limit{"T", 1000.0, std::nullopt}}, .domain = {}}};
  s.slices = {Slice{.id = 1, .axis = "level", .value = 500.0, .var = "T"}};
  const ResolvedScene scene = resolve_scene(s, store->manifest(), "test");
  const auto& m = store->manifest();
  std::size_t checked = 0;
  for (NodeId node = 0; node < store->octree().node_count(); ++node) {
    if (store->octree().key(node).level != 0) continue;
    const NodeExtraction e = extract_node(*store, nullptr, scene, 0, node);
    const SliceResult& r = e.slices[0];
    if (r.outcome != NodeOutcome::kMesh) continue;
    const NodeGeometry g = node_geometry(*store, node);
    // The node's bricks hold the samples: compare with a full read of the level-0 brick.
    const Brick brick = store->read_brick(0, 0, node);
    const std::size_t z = static_cast<std::size_t>(
        std::find(g.coords[2].begin(), g.coords[2].end(), 500.0) - g.coords[2].begin());
    ASSERT_LT(z, g.coords[2].size());
    for (std::size_t v = 0; v < r.mesh.vertex_count(); ++v) {
      const auto& p = r.mesh.positions[v];
      EXPECT_EQ(p[2], 500.0);
      const auto x = static_cast<std::size_t>(std::find(g.coords[0].begin(), g.coords[0].end(), p[0]) - g.coords[0].begin());
      const auto y = static_cast<std::size_t>(std::find(g.coords[1].begin(), g.coords[1].end(), p[1]) - g.coords[1].begin());
      const double sample = brick.sample((z * g.coords[1].size() + y) * g.coords[0].size() + x);
      if (std::isnan(sample)) {
        EXPECT_TRUE(std::isnan(r.mesh.attributes[0][v]));
      } else {
        EXPECT_EQ(r.mesh.attributes[0][v], static_cast<float>(sample));
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 36u * 33u / 2);
  EXPECT_EQ(m.z.units, "millibars");
}

}  // namespace
}  // namespace strielad
