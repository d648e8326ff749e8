// SPDX-License-Identifier: Apache-2.0
// The structured-grid clip reference (peers/vtk_structured_clip.h) on lattices where the
// answer is known: a sheared lattice (an affine image of the index lattice) cut by a field
// linear in the index, whose region is a parallelepiped, and malformed input refused.
#include "peers/vtk_structured_clip.h"

#include <gtest/gtest.h>

#include <cmath>

#include "extract/mesh_metrics.h"
#include "support/expect_error.h"

namespace strielad::peers {
namespace {

// Point (i, j, k) at A (i, j, k) + (10, 20, 30), A = [[2, 0.5, 0], [0, 3, 0.25], [0.1, 0, 4]]
// (det = 24.0125); field 0 is i, field 1 is k.
StructuredPoints sheared(std::size_t ni, std::size_t nj, std::size_t nk) {
  StructuredPoints g;
  g.dims = {ni, nj, nk};
  g.fields.resize(2);
  for (std::size_t k = 0; k < nk; ++k) {
    for (std::size_t j = 0; j < nj; ++j) {
      for (std::size_t i = 0; i < ni; ++i) {
        const double x = double(i), y = double(j), z = double(k);
        g.positions.push_back({10 + 2 * x + 0.5 * y, 20 + 3 * y + 0.25 * z, 30 + 0.1 * x + 4 * z});
        g.fields[0].push_back(x);
        g.fields[1].push_back(z);
      }
    }
  }
  return g;
}

constexpr double kDet = 2 * (3 * 4 - 0.25 * 0) - 0.5 * (0 * 4 - 0.25 * 0.1) + 0 * (0 - 3 * 0.1);

TEST(VtkStructuredClipTest, AShearedBoxHasItsVolumeAndAClosedOutwardSurface) {
  // 1.5 <= i <= 3.25 and k <= 2.5 on a 6 x 4 x 5 lattice: 1.75 x 3 x 2.5 index units.
  const StructuredClipMeasures m =
      clip_structured_grid(sheared(6, 4, 5), {{.field = 0, .min = 1.5, .max = 3.25},
                                              {.field = 1, .max = 2.5}});
  const double volume = kDet * 1.75 * 3 * 2.5;
  EXPECT_NEAR(m.volume, volume, 1e-9 * volume);
  EXPECT_GT(m.cells, 0u);
  EXPECT_EQ(m.boundary_edges, 0u);
  EXPECT_EQ(m.non_manifold_edges, 0u);
  EXPECT_TRUE(check_mesh(m.surface).closed());
  EXPECT_NEAR(enclosed_volume(m.surface), volume, 1e-9 * volume);  // outward
  EXPECT_NEAR(m.surface_area, surface_area(m.surface), 1e-9 * m.surface_area);
}

TEST(VtkStructuredClipTest, AnEmptyRegionMeasuresNothing) {
  const StructuredClipMeasures m = clip_structured_grid(sheared(3, 3, 3), {{.field = 0, .min = 5}});
  EXPECT_EQ(m.cells, 0u);
  EXPECT_EQ(m.volume, 0.0);
  EXPECT_TRUE(m.surface.triangles.empty());
}

TEST(VtkStructuredClipTest, MalformedInputIsRefused) {
  using testing::expect_error;
  StructuredPoints g = sheared(3, 3, 3);
  expect_error([&] { clip_structured_grid(g, {}); }, ErrorCode::kInvalidArgument, {"no limit"});
  expect_error([&] { clip_structured_grid(g, {{.field = 2, .max = 1}}); },
               ErrorCode::kInvalidArgument, {"field 2"});
  expect_error([&] { clip_structured_grid(g, {{.field = 0, .min = 2, .max = 1}}); },
               ErrorCode::kInvalidArgument, {"field 0"});
  g.fields[1].pop_back();
  expect_error([&] { clip_structured_grid(g, {{.field = 0, .max = 1}}); },
               ErrorCode::kInvalidArgument, {"field 1 has 26 values for 27 points"});
  g = sheared(3, 3, 3);
  g.positions[4][1] = NAN;
  expect_error([&] { clip_structured_grid(g, {{.field = 0, .max = 1}}); },
               ErrorCode::kInvalidArgument, {"point 4"});
  g.dims = {1, 9, 3};
  expect_error([&] { clip_structured_grid(g, {{.field = 0, .max = 1}}); },
               ErrorCode::kInvalidArgument, {"1x9x3"});
}

}  // namespace
}  // namespace strielad::peers
