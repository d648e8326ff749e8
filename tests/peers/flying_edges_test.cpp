// SPDX-License-Identifier: Apache-2.0
// vtkFlyingEdges3D as a peer (peers/vtk_paper_pipeline.h): run in index space and mapped
// to uneven, descending axes, it gives the sphere's area and volume, oriented towards
// larger values; the surface is open where the node cuts it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "extract/mesh_metrics.h"
#include "peers/peer_mesh.h"
#include "peers/sphere_samples.h"
#include "peers/vtk_paper_pipeline.h"
#include "support/expect_error.h"

namespace strielad::peers {
namespace {

TEST(FlyingEdgesTest, SphereOnUnevenAxesHasItsAreaAndIsOrientedOutward) {
  const NodeSamples s = testing::sphere_node(33);
  const double radius = 0.35;
  const PeerResult r = run_flying_edges(s, 0, radius);
  ASSERT_FALSE(r.mesh.empty());
  EXPECT_EQ(r.cells, 32u * 32u * 32u);
  EXPECT_GT(r.seconds, 0.0);
  const double area = 4 * std::numbers::pi * radius * radius;
  EXPECT_NEAR(surface_area(r.mesh), area, 0.02 * area);
  EXPECT_TRUE(r.closed);  // the sphere lies inside the node
  EXPECT_NEAR(r.divergence_volume, testing::ball_volume(radius), 0.015 * testing::ball_volume(radius));
  EXPECT_GT(testing::fraction_pointing_away(r.mesh, {0.5, 0.5, 0.5}), 0.999);
  for (const auto& p : r.mesh.positions) {
    EXPECT_NEAR(testing::distance(p[0], p[1], p[2], {0.5, 0.5, 0.5}), radius, 0.01);
  }
}

TEST(FlyingEdgesTest, SurfaceCutByTheNodeIsOpen) {
  const NodeSamples s = testing::sphere_node(21, {0.0, 0.5, 0.5});
  const PeerResult r = run_flying_edges(s, 0, 0.35);
  EXPECT_FALSE(r.closed);
  EXPECT_GT(r.boundary_edges, 0u);
  const double half = 2 * std::numbers::pi * 0.35 * 0.35;
  EXPECT_NEAR(surface_area(r.mesh), half, 0.03 * half);
}

TEST(FlyingEdgesTest, NanSamplesCountAsBelowTheIsoValue) {
  NodeSamples s;
  for (int a = 0; a < 3; ++a) s.coords[a] = testing::stretched_axis(9, 0.0, 8.0, 1.0);
  testing::add_field(s, [](double, double, double) { return 1.0; });
  s.fields[0][(4 * 9 + 4) * 9 + 4] = NAN;
  const PeerResult r = run_flying_edges(s, 0, 0.5);
  // A closed surface around the NaN sample (an octahedron through its neighbours),
  // oriented towards larger values: outward of the region field <= iso around it.
  EXPECT_TRUE(r.closed);
  EXPECT_NEAR(r.divergence_volume, 4.0 / 3.0, 1e-3);
  for (const auto& p : r.mesh.positions) {
    for (int a = 0; a < 3; ++a) EXPECT_TRUE(std::isfinite(p[a]));
  }
}

TEST(FlyingEdgesTest, BadArgumentsAreInvalidArgument) {
  const NodeSamples s = testing::sphere_node(5);
  testing::expect_error([&] { run_flying_edges(s, 1, 0.3); }, ErrorCode::kInvalidArgument,
                        {"field 1 does not exist"});
  testing::expect_error([&] { run_flying_edges(s, 0, INFINITY); }, ErrorCode::kInvalidArgument,
                        {"not finite"});
}

}  // namespace
}  // namespace strielad::peers
