// SPDX-License-Identifier: Apache-2.0
// A crossing a tiny fraction of a cell from a sample is a distinct lattice point, but in
// axis coordinates c0 + f (c1 - c0) it can round onto the sample itself when the axis'
// spacing is tiny against its values. The kernel looks for that only on axes where it
// can happen (spacing under 2^-18 of the values) and for the general clipper's points;
// where it happens, the triangles with two vertices at one position and those whose
// three distinct vertices end up on one line must go, and the mesh must stay closed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "extract/mesh_metrics.h"
#include "extract/node_extractor.h"

namespace strielad {
namespace {

// A 9 x 6 x 5 node whose x axis starts at `origin` with spacing `spacing`; the field is
// the x index minus 3 + 1e-8, so a limit at 0 crosses every x edge from index 3 to 4 at
// 1e-8 of the cell (well beyond the kernel's snap to corners, 2^-30).
NodeSamples sliver_node(double origin, double spacing) {
  NodeSamples s;
  s.coords = {std::vector<double>(9), {0, 1, 2, 3, 4, 5}, {0, 10, 20, 30, 40}};
  for (std::size_t i = 0; i < 9; ++i) s.coords[0][i] = origin + spacing * double(i);
  const auto d = s.dims();
  std::vector<float> values(s.sample_count());
  for (std::size_t z = 0, i = 0; z < d[2]; ++z) {
    for (std::size_t y = 0; y < d[1]; ++y) {
      for (std::size_t x = 0; x < d[0]; ++x, ++i) {
        values[i] = static_cast<float>(double(x) - 3.0 - 1e-8);
      }
    }
  }
  s.fields = {values};
  return s;
}

// The region x index <= 3 + 1e-8: its faces on the node's y and z sides run from the
// samples at index 3 to the crossings just beyond them.
ExtractRequest below_the_crossing() {
  ExtractRequest r;
  r.subvolume_id = 1;
  r.limits = {{0, -kUnbounded, 0.0}};
  return r;
}

std::size_t triangles_with_coincident_vertices(const Mesh& mesh) {
  std::size_t n = 0;
  for (const auto& t : mesh.triangles) {
    const auto& a = mesh.positions[t[0]];
    const auto& b = mesh.positions[t[1]];
    const auto& c = mesh.positions[t[2]];
    n += a == b || b == c || a == c ? 1 : 0;
  }
  return n;
}

// Closed and oriented, every edge in exactly two triangles, unit normals.
void expect_closed(const Mesh& mesh) {
  const MeshCheck c = check_mesh(mesh);
  EXPECT_TRUE(c.closed() && c.nonmanifold_edges == 0 && c.bad_normals == 0)
      << c.open_edges << " open, " << c.nonmanifold_edges << " non-manifold, "
      << c.misoriented_edges << " misoriented edges, " << c.bad_normals << " bad normals";
  EXPECT_GT(mesh.triangles.size(), 0u);
}

TEST(VerticesRoundedOntoSamples, CollapsedSliversOnATightlySpacedAxisAreRemoved) {
  // Spacing 1e-5 at 1e9 (1e-14 of the values) and 2^-30 at 1 (2^-30 of them): f (c1 -
  // c0) is far below half an ulp of c0, so every crossing lands on its sample's x.
  for (const auto& [origin, spacing] : {std::pair{1e9, 1e-5}, std::pair{1.0, 0x1p-30}}) {
    SCOPED_TRACE(origin);
    const NodeSamples s = sliver_node(origin, spacing);
    const Mesh mesh = extract_node_mesh(s, below_the_crossing());
    // Without the check: 36 such triangles and 36 edges with four triangles; without
    // splitting the collinear slivers: 18 zero-area triangles.
    EXPECT_EQ(triangles_with_coincident_vertices(mesh), 0u);
    expect_closed(mesh);
    EXPECT_EQ(check_mesh(mesh).degenerate_triangles, 0u);
    for (const auto& p : mesh.positions) EXPECT_LE(p[0], s.coords[0][3]);
    // The sliver's volume went with it: the box up to index 3.
    const double box = (s.coords[0][3] - s.coords[0][0]) * 5.0 * 40.0;
    EXPECT_NEAR(enclosed_volume(mesh), box, 1e-9 * box);
  }
}

TEST(VerticesRoundedOntoSamples, SliversOnOrdinaryAxesStay) {
  // Spacing 0.025 degrees at 10 E (not checked), and 0.5 m at 1e6 m (5e-7 of the
  // values: checked, but nothing rounds there): the crossings stay beyond index 3 and
  // the mesh is clean.
  for (const auto& [origin, spacing] : {std::pair{10.0, 0.025}, std::pair{1e6, 0.5}}) {
    SCOPED_TRACE(origin);
    const NodeSamples s = sliver_node(origin, spacing);
    const Mesh mesh = extract_node_mesh(s, below_the_crossing());
    expect_closed(mesh);
    EXPECT_EQ(check_mesh(mesh).degenerate_triangles, 0u);
    double largest_x = -1e300;
    for (const auto& p : mesh.positions) largest_x = std::max(largest_x, p[0]);
    EXPECT_GT(largest_x, s.coords[0][3]);
    EXPECT_LT(largest_x, s.coords[0][3] + 1e-7 * spacing);
  }
}

}  // namespace
}  // namespace strielad
