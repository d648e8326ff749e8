// SPDX-License-Identifier: Apache-2.0
// The paper's VTK clip pipeline (peers/vtk_paper_pipeline.h) gives closed, outward
// meshes of the right volume on uneven and descending axes: a ball, a shell, a lens, a
// domain box, and fill (NaN) samples counted as outside.
#include "peers/vtk_paper_pipeline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "extract/mesh_metrics.h"
#include "peers/peer_mesh.h"
#include "peers/sphere_samples.h"
#include "support/expect_error.h"

namespace strielad::peers {
namespace {

using testing::ball_volume;
using testing::sphere_node;

constexpr std::array<double, 3> kCentre{0.5, 0.5, 0.5};

void expect_sane(const PeerResult& r) {
  ASSERT_EQ(r.mesh.normals.size(), r.mesh.positions.size());
  ASSERT_EQ(r.mesh.face_kinds.size(), r.mesh.triangles.size());
  for (std::size_t v = 0; v < r.mesh.vertex_count(); ++v) {
    for (int a = 0; a < 3; ++a) {
      ASSERT_TRUE(std::isfinite(r.mesh.positions[v][a])) << "vertex " << v;
      ASSERT_TRUE(std::isfinite(r.mesh.normals[v][a])) << "vertex " << v;
    }
  }
  // vtkMassProperties and the divergence sum agree on a closed surface.
  if (r.closed) {
    EXPECT_NEAR(r.mass_properties_volume, r.divergence_volume,
                1e-4 * std::abs(r.divergence_volume));
  }
  const EdgeCounts edges = count_open_edges(r.mesh);
  EXPECT_EQ(edges.boundary, r.boundary_edges);
  EXPECT_EQ(edges.non_manifold, r.non_manifold_edges);
}

TEST(VtkPaperPipelineTest, BallOnUnevenDescendingAxesIsClosedOutwardAndHasItsVolume) {
  const NodeSamples s = sphere_node(33);
  const double radius = 0.35;
  PaperSubvolume sv;
  sv.id = 4;
  sv.limits = {{.field = 0, .min = std::nullopt, .max = radius}};
  const PeerResult r = run_paper_pipeline(s, sv);
  expect_sane(r);
  EXPECT_EQ(r.mesh.subvolume_id, 4u);
  EXPECT_EQ(r.cells, 32u * 32u * 32u);
  EXPECT_GT(r.seconds, 0.0);
  EXPECT_TRUE(r.closed) << r.boundary_edges << " boundary, " << r.non_manifold_edges
                        << " non-manifold edges";
  EXPECT_GT(r.divergence_volume, 0.0) << "triangles must be counter-clockwise from outside";
  EXPECT_NEAR(r.divergence_volume, ball_volume(radius), 0.015 * ball_volume(radius));
  EXPECT_GT(testing::fraction_pointing_away(r.mesh, kCentre), 0.999);
  for (auto kind : r.mesh.face_kinds) EXPECT_EQ(kind, FaceKind::kLimit);
}

TEST(VtkPaperPipelineTest, BallCutByTheNodeIsClosedByNodeBoundaryFaces) {
  // Centre on the node's x = 0 face: half a ball, closed by a disc on that face.
  const NodeSamples s = sphere_node(33, {0.0, 0.5, 0.5});
  PaperSubvolume sv;
  sv.limits = {{.field = 0, .max = 0.35}};
  const PeerResult r = run_paper_pipeline(s, sv);
  expect_sane(r);
  EXPECT_TRUE(r.closed);
  EXPECT_NEAR(r.divergence_volume, ball_volume(0.35) / 2, 0.015 * ball_volume(0.35) / 2);
  std::size_t boundary = 0;
  for (std::size_t t = 0; t < r.mesh.triangle_count(); ++t) {
    if (r.mesh.face_kinds[t] != FaceKind::kNodeBoundary) continue;
    ++boundary;
    for (auto v : r.mesh.triangles[t]) EXPECT_EQ(r.mesh.positions[v][0], 0.0);
  }
  EXPECT_GT(boundary, 0u);
}

TEST(VtkPaperPipelineTest, MinAndMaxLimitsGiveAShellWithAnInwardFacingCavity) {
  const NodeSamples s = sphere_node(33);
  PaperSubvolume sv;
  sv.limits = {{.field = 0, .min = 0.2, .max = 0.4}};
  const PeerResult r = run_paper_pipeline(s, sv);
  expect_sane(r);
  EXPECT_TRUE(r.closed);
  const double shell = ball_volume(0.4) - ball_volume(0.2);
  EXPECT_NEAR(r.divergence_volume, shell, 0.015 * shell);
  // Outer wall normals point away from the centre, the cavity's towards it.
  Mesh outer = r.mesh, inner = r.mesh;
  auto keep = [](Mesh& m, bool want_outer) {
    std::vector<std::array<std::uint32_t, 3>> tris;
    std::vector<FaceKind> kinds;
    for (const auto& t : m.triangles) {
      const auto& p = m.positions[t[0]];
      const double r0 = testing::distance(p[0], p[1], p[2], kCentre);
      if ((r0 > 0.3) == want_outer) {
        tris.push_back(t);
        kinds.push_back(FaceKind::kLimit);
      }
    }
    m.triangles = tris;
    m.face_kinds = kinds;
  };
  keep(outer, true);
  keep(inner, false);
  EXPECT_GT(testing::fraction_pointing_away(outer, kCentre), 0.999);
  EXPECT_GT(testing::fraction_pointing_away(inner, kCentre, -1.0), 0.999);
}

TEST(VtkPaperPipelineTest, TwoFieldLimitsIntersectToALens) {
  NodeSamples s = sphere_node(33, {0.38, 0.5, 0.5});
  const std::size_t g = testing::add_field(s, [](double x, double y, double z) {
    return testing::distance(x, y, z, {0.62, 0.5, 0.5});
  });
  const double radius = 0.3, d = 0.24;
  PaperSubvolume sv;
  sv.limits = {{.field = 0, .max = radius}, {.field = g, .max = radius}};
  const PeerResult r = run_paper_pipeline(s, sv);
  expect_sane(r);
  EXPECT_TRUE(r.closed);
  const double lens = std::numbers::pi * (4 * radius + d) * (2 * radius - d) * (2 * radius - d) / 12;
  EXPECT_NEAR(r.divergence_volume, lens, 0.02 * lens);
}

TEST(VtkPaperPipelineTest, DomainBoxOfAnEverywhereInsideFieldIsTheBox) {
  NodeSamples s = sphere_node(21);
  PaperSubvolume sv;
  sv.limits = {{.field = 0, .min = -1.0}};  // distance >= -1: everywhere
  AxisBox box;
  box.lo = {0.137, 0.21, 0.3};
  box.hi = {0.71, 0.853, 0.6789};
  sv.domain = box;
  const PeerResult r = run_paper_pipeline(s, sv);
  expect_sane(r);
  EXPECT_TRUE(r.closed);
  const double volume = (0.71 - 0.137) * (0.853 - 0.21) * (0.6789 - 0.3);
  EXPECT_NEAR(r.divergence_volume, volume, 1e-5 * volume);
  for (auto kind : r.mesh.face_kinds) EXPECT_EQ(kind, FaceKind::kDomainBox);

  // A box reaching past the node on +x: that side is the node's face.
  box.hi[0] = 2.0;
  sv.domain = box;
  const PeerResult past = run_paper_pipeline(s, sv);
  expect_sane(past);
  EXPECT_TRUE(past.closed);
  EXPECT_NEAR(past.divergence_volume, (1.0 - 0.137) * (0.853 - 0.21) * (0.6789 - 0.3), 1e-5);
  std::size_t node_faces = 0;
  for (std::size_t t = 0; t < past.mesh.triangle_count(); ++t) {
    if (past.mesh.face_kinds[t] == FaceKind::kNodeBoundary) {
      ++node_faces;
      for (auto v : past.mesh.triangles[t]) EXPECT_EQ(past.mesh.positions[v][0], 1.0);
    }
  }
  EXPECT_GT(node_faces, 0u);

  // A box missing the node: nothing.
  box.lo[0] = 3.0;
  box.hi[0] = 4.0;
  sv.domain = box;
  const PeerResult none = run_paper_pipeline(s, sv);
  EXPECT_TRUE(none.mesh.empty());
  EXPECT_FALSE(none.closed);
}

TEST(VtkPaperPipelineTest, NanSamplesAreOutside) {
  // Uniform lattice, field 1 everywhere except one interior NaN sample.
  NodeSamples s;
  for (int a = 0; a < 3; ++a) s.coords[a] = testing::stretched_axis(9, 0.0, 8.0, 1.0);
  testing::add_field(s, [](double, double, double) { return 1.0; });
  const std::size_t attribute = testing::add_field(s, [](double x, double y, double z) {
    return x + 2 * y + 3 * z;
  });
  s.fields[0][(4 * 9 + 4) * 9 + 4] = NAN;  // sample (4, 4, 4)
  PaperSubvolume sv;
  sv.limits = {{.field = 0, .min = 0.5}};
  PaperPipelineOptions options;
  options.attributes = {{.name = "g", .field = attribute}};

  const PeerResult far = run_paper_pipeline(s, sv, options);
  expect_sane(far);
  EXPECT_TRUE(far.closed);
  // The surface runs through the NaN sample's six neighbours: an octahedron of volume
  // 4/3 (cell size 1) is cut out of the 8^3 cube.
  EXPECT_NEAR(far.divergence_volume, 512.0 - 4.0 / 3.0, 1e-3);
  // Attributes are carried (linear field: interpolation is exact).
  ASSERT_EQ(far.mesh.attribute_names, std::vector<std::string>{"g"});
  for (std::size_t v = 0; v < far.mesh.vertex_count(); ++v) {
    const auto& p = far.mesh.positions[v];
    EXPECT_NEAR(far.mesh.attributes[0][v], p[0] + 2 * p[1] + 3 * p[2], 1e-4);
  }

  options.nan_policy = NanPolicy::kDropCells;
  const PeerResult drop = run_paper_pipeline(s, sv, options);
  expect_sane(drop);
  EXPECT_TRUE(drop.closed);
  EXPECT_NEAR(drop.divergence_volume, 512.0 - 8.0, 1e-3);  // the 8 cells around it

  // All NaN: nothing.
  for (float& v : s.fields[0]) v = NAN;
  EXPECT_TRUE(run_paper_pipeline(s, sv).mesh.empty());
}

TEST(VtkPaperPipelineTest, EmptyRegionGivesAnEmptyMesh) {
  const NodeSamples s = sphere_node(9);
  PaperSubvolume sv;
  sv.limits = {{.field = 0, .min = 5.0}};
  const PeerResult r = run_paper_pipeline(s, sv);
  EXPECT_TRUE(r.mesh.empty());
  EXPECT_FALSE(r.closed);
  EXPECT_EQ(r.divergence_volume, 0.0);
}

TEST(VtkPaperPipelineTest, BadArgumentsAreInvalidArgument) {
  const NodeSamples s = sphere_node(5);
  PaperSubvolume sv;
  sv.limits = {{.field = 3, .max = 1.0}};
  testing::expect_error([&] { run_paper_pipeline(s, sv); }, ErrorCode::kInvalidArgument,
                        {"field 3 does not exist"});
  sv.limits = {{.field = 0, .min = 2.0, .max = 1.0}};
  testing::expect_error([&] { run_paper_pipeline(s, sv); }, ErrorCode::kInvalidArgument,
                        {"min 2 > max 1"});
  sv.limits = {{.field = 0, .min = NAN}};
  testing::expect_error([&] { run_paper_pipeline(s, sv); }, ErrorCode::kInvalidArgument, {"NaN"});
  NodeSamples bent = s;
  bent.coords[2][2] = bent.coords[2][1];
  sv.limits = {{.field = 0, .max = 1.0}};
  testing::expect_error([&] { run_paper_pipeline(bent, sv); }, ErrorCode::kInvalidArgument,
                        {"axis z is not strictly monotonic"});
}

}  // namespace
}  // namespace strielad::peers
