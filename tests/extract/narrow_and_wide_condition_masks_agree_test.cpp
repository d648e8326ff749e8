// SPDX-License-Identifier: Apache-2.0
// build_conditions keeps 16-bit masks per sample when a request can make at most 16
// conditions and 64-bit masks beyond: both widths must hold the same bits, and the
// kernel must make the same mesh from either.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "extract/conditions.h"
#include "extract/node_extractor.h"

namespace strielad {
namespace {

// Two fields on a 21 x 17 x 13 lattice: a distance from a point and a tilted plane,
// with a few missing samples (a validity condition).
NodeSamples shell_and_plane() {
  NodeSamples s;
  s.coords = {std::vector<double>(21), std::vector<double>(17), std::vector<double>(13)};
  for (int a = 0; a < 3; ++a) {
    for (std::size_t i = 0; i < s.coords[a].size(); ++i) s.coords[a][i] = 0.1 * double(i * i);
  }
  const auto d = s.dims();
  std::vector<float> distance(s.sample_count()), plane(s.sample_count());
  for (std::size_t z = 0, i = 0; z < d[2]; ++z) {
    for (std::size_t y = 0; y < d[1]; ++y) {
      for (std::size_t x = 0; x < d[0]; ++x, ++i) {
        const double dx = double(x) - 9.3, dy = double(y) - 7.6, dz = double(z) - 5.1;
        distance[i] = static_cast<float>(std::sqrt(dx * dx + dy * dy + dz * dz));
        plane[i] = static_cast<float>(0.7 * double(x) - 0.4 * double(y) + 0.2 * double(z));
      }
    }
  }
  distance[(5 * d[1] + 8) * d[0] + 10] = std::numeric_limits<float>::quiet_NaN();
  plane[(3 * d[1] + 2) * d[0] + 4] = std::numeric_limits<float>::infinity();
  s.fields = {distance, plane};
  return s;
}

// A shell between two distances, above a plane, inside a domain box: 8 conditions
// cross the node of the 10 the request can make (three limit sides, a validity
// condition, six box sides), so narrow masks.
ExtractRequest narrow_request() {
  ExtractRequest r;
  r.subvolume_id = 3;
  r.limits = {{0, 2.5, 6.0}, {1, -2.0, kUnbounded}};
  r.box = {{{1.0, 30.0}, {0.5, 25.6}, {-1.0, 12.0}}};
  return r;
}

// The same region with seven more limits that hold at every sample: 24 possible
// conditions, so 64-bit masks, but the conditions that cross the node are the same.
ExtractRequest wide_request() {
  ExtractRequest r = narrow_request();
  for (int k = 0; k < 7; ++k) r.limits.push_back({std::uint32_t(k % 2), -1e30, 1e30});
  return r;
}

TEST(NarrowAndWideConditionMasks, WidthFollowsTheConditionsARequestCanMake) {
  const NodeSamples s = shell_and_plane();
  EXPECT_TRUE(build_conditions(s, narrow_request()).narrow);
  EXPECT_FALSE(build_conditions(s, wide_request()).narrow);
  ExtractRequest sixteen;  // 7 two-sided limits + validity = 15, + one more side = 16
  for (int k = 0; k < 7; ++k) sixteen.limits.push_back({0, -1e30, 1e30});
  sixteen.limits.push_back({1, -1e30, kUnbounded});
  EXPECT_TRUE(build_conditions(s, sixteen).narrow);
  sixteen.limits.back().max = 1e30;
  EXPECT_FALSE(build_conditions(s, sixteen).narrow);
}

TEST(NarrowAndWideConditionMasks, BothWidthsHoldTheSameBitsPerSample) {
  const NodeSamples s = shell_and_plane();
  const ConditionSet narrow = build_conditions(s, narrow_request());
  const ConditionSet wide = build_conditions(s, wide_request());
  ASSERT_TRUE(narrow.narrow);
  ASSERT_FALSE(wide.narrow);
  ASSERT_EQ(narrow.conditions.size(), 8u);
  ASSERT_EQ(wide.conditions.size(), 8u);
  EXPECT_EQ(narrow.all, wide.all);
  ASSERT_EQ(narrow.inside16.size(), s.sample_count());
  ASSERT_EQ(wide.inside64.size(), s.sample_count());
  std::size_t differing = 0, mixed = 0;
  for (std::size_t i = 0; i < s.sample_count(); ++i) {
    differing += narrow.inside16[i] != wide.inside64[i] ? 1 : 0;
    mixed += narrow.inside16[i] != 0 && narrow.inside16[i] != narrow.all ? 1 : 0;
  }
  EXPECT_EQ(differing, 0u);
  EXPECT_GT(mixed, 100u);  // the bits say something: samples inside some conditions only
}

TEST(NarrowAndWideConditionMasks, KernelMakesTheSameMeshFromEither) {
  const NodeSamples s = shell_and_plane();
  ExtractStats narrow_stats, wide_stats;
  const Mesh narrow = extract_node_mesh(s, narrow_request(), &narrow_stats);
  const Mesh wide = extract_node_mesh(s, wide_request(), &wide_stats);
  ASSERT_GT(narrow.triangles.size(), 500u);
  EXPECT_GT(narrow_stats.clipped_tets, 0u);  // cells crossed by several conditions too
  EXPECT_EQ(narrow.positions, wide.positions);
  EXPECT_EQ(narrow.normals, wide.normals);
  EXPECT_EQ(narrow.triangles, wide.triangles);
  EXPECT_EQ(narrow.face_kinds, wide.face_kinds);
  EXPECT_EQ(narrow_stats.cut_cells, wide_stats.cut_cells);
  EXPECT_EQ(narrow_stats.inside_cells, wide_stats.inside_cells);
}

}  // namespace
}  // namespace strielad
