// SPDX-License-Identifier: Apache-2.0
// Meshes of a curvilinear store (index axes, 2-D longitudes and latitudes in GEOMETRY)
// placed in the lonlat, metric and ecef frames: vertices on the grid's columns at the
// stored coordinates exactly, vertices on lattice edges linear between them, closed and
// outward meshes in every frame; the frames refused without the coordinates; geographic
// boxes evaluated per sample on the stored coordinates.
#include <gtest/gtest.h>

#include <cmath>

#include "extract/level_extraction.h"
#include "extract/mesh_metrics.h"
#include "extract/output_frame.h"
#include "format/geometry_field.h"
#include "scene/scene.h"
#include "store/store.h"
#include "support/expect_error.h"
#include "support/geometry_store.h"
#include "support/temp_dir.h"

namespace strielad {
namespace {

testing::GeometryStoreSpec curvilinear_spec() {
  testing::GeometryStoreSpec spec;
  spec.nx = 9;
  spec.ny = 8;
  spec.nz = 6;
  spec.steps = 1;
  spec.brick = 4;
  spec.curvilinear = true;
  spec.surface = true;
  spec.field = testing::GeometryField::kInvariant;
  return spec;
}

// Every level-0 node's mesh of `ta` within [lo, hi], carrying the geometry's height.
std::vector<Mesh> meshes(const Store& store, double lo, double hi,
                         std::optional<GeographicBox> box = std::nullopt) {
  const format::Manifest& m = store.manifest();
  Scene scene;
  SubVolume sv;
  sv.id = 1;
  sv.limits.push_back(Limit{"ta", lo, hi});
  sv.geographic = box;
  scene.subvolumes.push_back(sv);
  scene.attributes.push_back(format::geometry_field_name(m));
  LevelExtractionOptions o;
  o.merge_face_squares = false;
  LevelExtraction level = extract_level(store, resolve_scene(scene, m, "test scene"), o);
  std::vector<Mesh> out;
  for (NodeExtraction& n : level.nodes) {
    for (SubVolumeResult& r : n.results) {
      if (r.outcome == NodeOutcome::kMesh) out.push_back(std::move(r.mesh));
    }
  }
  return out;
}

TEST(CurvilinearPlacementTest, ColumnsSitAtTheirStoredCoordinatesAndEdgesBetween) {
  const testing::TempDir dir;
  const auto spec = curvilinear_spec();
  write_geometry_store(dir / "store", spec);
  const auto store = Store::open(dir / "store");
  const format::Manifest& m = store->manifest();
  const auto coordinates = store->horizontal_coordinates();
  ASSERT_TRUE(coordinates && coordinates->has_coordinates());
  const FrameTransform lonlat(m, OutputFrame::kLonLat, choose_vertical_placement(m), coordinates);
  EXPECT_FALSE(lonlat.affine());
  // ta = x + 10 y + 100 z: the band cuts the lattice between columns and levels.
  std::vector<Mesh> placed = meshes(*store, 215.5, 433.25);
  ASSERT_FALSE(placed.empty());
  std::size_t on_columns = 0, on_x_edges = 0;
  for (Mesh& mesh : placed) {
    const std::vector<std::array<double, 3>> axis = mesh.positions;
    lonlat.apply(mesh);
    for (std::size_t v = 0; v < axis.size(); ++v) {
      const double i = axis[v][0], j = axis[v][1];
      const auto column = [&](std::size_t ci, std::size_t cj) {
        const std::size_t k = cj * coordinates->nx + ci;
        return std::array<double, 2>{coordinates->lon[k], coordinates->lat[k]};
      };
      if (i == std::floor(i) && j == std::floor(j)) {
        const auto c = column(std::size_t(i), std::size_t(j));
        ASSERT_EQ(mesh.positions[v][0], c[0]);
        ASSERT_EQ(mesh.positions[v][1], c[1]);
        ++on_columns;
      } else if (j == std::floor(j)) {
        const std::size_t i0 = std::min<std::size_t>(std::size_t(i), coordinates->nx - 2);
        const double f = i - double(i0);
        const auto a = column(i0, std::size_t(j)), b = column(i0 + 1, std::size_t(j));
        ASSERT_NEAR(mesh.positions[v][0], (1 - f) * a[0] + f * b[0], 1e-12);
        ASSERT_NEAR(mesh.positions[v][1], (1 - f) * a[1] + f * b[1], 1e-12);
        ++on_x_edges;
      }
    }
  }
  EXPECT_GT(on_columns, 0u);
  EXPECT_GT(on_x_edges, 0u);
}

TEST(CurvilinearPlacementTest, MeshesStayClosedAndOutwardInEveryFrame) {
  const testing::TempDir dir;
  write_geometry_store(dir / "store", curvilinear_spec());
  const auto store = Store::open(dir / "store");
  const format::Manifest& m = store->manifest();
  for (const OutputFrame frame : {OutputFrame::kLocalMetric, OutputFrame::kEcef}) {
    const FrameTransform transform(m, frame, choose_vertical_placement(m),
                                   store->horizontal_coordinates());
    const std::vector<Mesh> axis_meshes = meshes(*store, 215.5, 433.25);
    for (Mesh mesh : axis_meshes) {
      transform.apply(mesh);
      EXPECT_TRUE(check_mesh(mesh).closed());
      EXPECT_GT(enclosed_volume(mesh), 0) << output_frame_name(frame);
    }
  }
}

TEST(CurvilinearPlacementTest, FramesOtherThanAxisNeedTheCoordinates) {
  const testing::TempDir dir;
  write_geometry_store(dir / "store", curvilinear_spec());
  const auto store = Store::open(dir / "store");
  const format::Manifest& m = store->manifest();
  testing::expect_error([&] { FrameTransform(m, OutputFrame::kLonLat, choose_vertical_placement(m)); },
                        ErrorCode::kUnsupported, {"curvilinear", "GEOMETRY"});
  FrameTransform axis(m, OutputFrame::kAxis, choose_vertical_placement(m));  // index space
  EXPECT_TRUE(axis.affine());
}

TEST(CurvilinearPlacementTest, AGeographicBoxIsEvaluatedOnTheStoredCoordinates) {
  const testing::TempDir dir;
  const auto spec = curvilinear_spec();
  write_geometry_store(dir / "store", spec);
  const auto store = Store::open(dir / "store");
  const format::Manifest& m = store->manifest();
  const auto coordinates = store->horizontal_coordinates();
  const FrameTransform lonlat(m, OutputFrame::kLonLat, choose_vertical_placement(m), coordinates);
  // Latitudes up to 46.6: a bound between the grid's rows, bent by the grid's shear.
  GeographicBox box;
  box.lat = AxisRange{-90, 46.6};
  std::vector<Mesh> placed = meshes(*store, -1e9, 1e9, box);
  ASSERT_FALSE(placed.empty());
  std::size_t on_bound = 0;
  for (Mesh& mesh : placed) {
    const std::vector<std::array<double, 3>> axis = mesh.positions;
    lonlat.apply(mesh);
    EXPECT_TRUE(check_mesh(mesh).closed());
    for (std::size_t v = 0; v < axis.size(); ++v) {
      // On a lattice edge (two integer index coordinates) the condition lat - 46.6 is
      // linear, and so is the placement: the vertex lies on the bound or inside.
      int integral = 0;
      for (int k = 0; k < 3; ++k) integral += axis[v][k] == std::floor(axis[v][k]);
      if (integral < 2) continue;
      EXPECT_LE(mesh.positions[v][1], 46.6 + 1e-9);
      on_bound += std::fabs(mesh.positions[v][1] - 46.6) < 1e-9;
    }
  }
  EXPECT_GT(on_bound, 0u);
}

}  // namespace
}  // namespace strielad
