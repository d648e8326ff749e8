// SPDX-License-Identifier: Apache-2.0
// extract_node_mesh with a caller's NodeMeshScratch: the mesh does not depend on what the
// scratch held before (other nodes, other sizes, a surface through samples that makes the
// kernel remove collapsed triangles), nor on whether it is this thread's scratch or a
// fresh one.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "extract/node_extractor.h"

namespace strielad {
namespace {

NodeSamples waves(std::size_t n, double phase, bool integer_values) {
  NodeSamples s;
  for (int a = 0; a < 3; ++a) {
    s.coords[a].resize(n);
    for (std::size_t i = 0; i < n; ++i) s.coords[a][i] = static_cast<double>(i) * (a == 2 ? -2.0 : 0.5);
  }
  std::vector<float> a(s.sample_count()), b(s.sample_count());
  std::size_t i = 0;
  for (std::size_t z = 0; z < n; ++z) {
    for (std::size_t y = 0; y < n; ++y) {
      for (std::size_t x = 0; x < n; ++x, ++i) {
        const double v = std::sin(0.4 * static_cast<double>(x) + phase) + std::cos(0.3 * static_cast<double>(y)) +
                         0.2 * static_cast<double>(z);
        a[i] = static_cast<float>(integer_values ? std::floor(2 * v) : v);
        b[i] = static_cast<float>(std::cos(0.25 * static_cast<double>(x + y)) - 0.1 * static_cast<double>(z));
      }
    }
  }
  s.fields = {a, b};
  return s;
}

ExtractRequest two_limits(double lo) {
  ExtractRequest r;
  r.limits = {{0, lo, 1.5}, {1, -0.5, kUnbounded}};  // two limits: tetrahedra and the clipper
  r.box[1] = {1.0, 6.0};
  r.attribute_fields = {1};
  r.attribute_names = {"b"};
  return r;
}

TEST(ReusedScratch, MeshesMatchFreshScratch) {
  struct Node {
    NodeSamples samples;
    ExtractRequest request;
  };
  // On integer values a limit of 0 passes through samples (corner crossings).
  const std::vector<Node> nodes{{waves(17, 0.0, false), two_limits(0.3)},
                                {waves(9, 1.0, true), two_limits(0.0)},
                                {waves(25, 2.0, false), two_limits(-0.2)},
                                {waves(9, 1.0, false), two_limits(0.3)}};
  std::vector<Mesh> fresh;
  for (const Node& n : nodes) {
    NodeMeshScratch scratch;
    fresh.push_back(extract_node_mesh(n.samples, n.request, scratch));
    ASSERT_FALSE(fresh.back().empty());
  }
  NodeMeshScratch reused;
  for (int round = 0; round < 2; ++round) {
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      const std::size_t i = round == 0 ? k : nodes.size() - 1 - k;
      EXPECT_EQ(extract_node_mesh(nodes[i].samples, nodes[i].request, reused), fresh[i]) << "node " << i;
      EXPECT_EQ(extract_node_mesh(nodes[i].samples, nodes[i].request), fresh[i]) << "node " << i;
    }
  }
}

}  // namespace
}  // namespace strielad
