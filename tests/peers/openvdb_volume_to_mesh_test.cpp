// SPDX-License-Identifier: Apache-2.0
// OpenVDB volumeToMesh as a peer (peers/openvdb_volume_to_mesh.h): run in index space and
// mapped to uneven, descending axes, it gives the sphere's area and volume, oriented towards
// larger values; the surface is open where the node cuts it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "extract/mesh_metrics.h"
#include "peers/peer_mesh.h"
#include "peers/sphere_samples.h"
#include "peers/openvdb_volume_to_mesh.h"
#include "support/expect_error.h"

namespace strielad::peers {
namespace {

TEST(OpenVdbVolumeToMeshTest, SphereOnUnevenAxesHasItsAreaAndIsOrientedOutward) {
  const NodeSamples s = testing::sphere_node(33);
  const double radius = 0.35;
  const PeerResult r = run_openvdb_volume_to_mesh(s, 0, radius);
  ASSERT_FALSE(r.mesh.empty());
  EXPECT_EQ(r.cells, 32u * 32u * 32u);
  EXPECT_GT(r.seconds, 0.0);
  const double area = 4 * std::numbers::pi * radius * radius;
  EXPECT_NEAR(surface_area(r.mesh), area, 0.02 * area);
  EXPECT_TRUE(r.closed);  // the sphere lies inside the node
  // Dual vertices lie inside the cells: the volume comes out a little small.
  EXPECT_NEAR(r.divergence_volume, testing::ball_volume(radius), 0.03 * testing::ball_volume(radius));
  EXPECT_GT(testing::fraction_pointing_away(r.mesh, {0.5, 0.5, 0.5}), 0.999);
  for (const auto& p : r.mesh.positions) {
    // Dual vertices sit inside cells, near but not on the sphere.
    EXPECT_NEAR(testing::distance(p[0], p[1], p[2], {0.5, 0.5, 0.5}), radius, 0.02);
  }
}

TEST(OpenVdbVolumeToMeshTest, SurfaceCutByTheNodeIsOpen) {
  const NodeSamples s = testing::sphere_node(21, {0.0, 0.5, 0.5});
  const PeerResult r = run_openvdb_volume_to_mesh(s, 0, 0.35);
  EXPECT_FALSE(r.closed);
  EXPECT_GT(r.boundary_edges, 0u);
  const double half = 2 * std::numbers::pi * 0.35 * 0.35;
  // Polygons reaching past the node's samples are dropped: up to half a cell less.
  EXPECT_NEAR(surface_area(r.mesh), half, 0.06 * half);
  EXPECT_LT(surface_area(r.mesh), half);
  for (const auto& p : r.mesh.positions) EXPECT_GE(p[0], 0.0);
}

TEST(OpenVdbVolumeToMeshTest, NanSamplesCountAsBelowTheIsoValue) {
  NodeSamples s;
  for (int a = 0; a < 3; ++a) s.coords[a] = testing::stretched_axis(9, 0.0, 8.0, 1.0);
  testing::add_field(s, [](double, double, double) { return 1.0; });
  s.fields[0][(4 * 9 + 4) * 9 + 4] = NAN;
  const PeerResult r = run_openvdb_volume_to_mesh(s, 0, 0.5);
  // A closed surface around the NaN sample (dual: one vertex per cell around it),
  // oriented towards larger values: outward of the region field <= iso around it.
  EXPECT_TRUE(r.closed);
  // Its vertices sit at the centres of the 8 cells around the sample: a volume of 8/27.
  EXPECT_NEAR(r.divergence_volume, 8.0 / 27.0, 1e-3);
  for (const auto& p : r.mesh.positions) {
    for (int a = 0; a < 3; ++a) EXPECT_TRUE(std::isfinite(p[a]));
  }
}

TEST(OpenVdbVolumeToMeshTest, BadArgumentsAreInvalidArgument) {
  const NodeSamples s = testing::sphere_node(5);
  testing::expect_error([&] { run_openvdb_volume_to_mesh(s, 1, 0.3); }, ErrorCode::kInvalidArgument,
                        {"field 1 does not exist"});
  testing::expect_error([&] { run_openvdb_volume_to_mesh(s, 0, INFINITY); }, ErrorCode::kInvalidArgument,
                        {"not finite"});
  testing::expect_error([&] { run_openvdb_volume_to_mesh(s, 0, 0.3, {.adaptivity = 2.0}); },
                        ErrorCode::kInvalidArgument, {"adaptivity 2 is outside [0, 1]"});
}

}  // namespace
}  // namespace strielad::peers
