// SPDX-License-Identifier: Apache-2.0
// remove_collapsed_triangles drops triangles with two vertices at one position and
// pairs of triangles over the same three positions in opposite orientations (the first
// of each orientation in order), then the vertices no triangle uses; checked against a
// plain map-based statement of that rule on random meshes full of coincident points.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>

#include "extract/collapsed_triangles.h"

namespace strielad {
namespace {

using Position = std::array<double, 3>;

// The rule as written, with ordered maps.
Mesh reference(Mesh mesh, bool look_for_sheets) {
  const std::size_t before = mesh.triangles.size();
  std::vector<bool> keep(before, true);
  bool any = false;
  for (std::size_t t = 0; t < before; ++t) {
    const auto& tri = mesh.triangles[t];
    const auto& p = mesh.positions;
    if (p[tri[0]] == p[tri[1]] || p[tri[1]] == p[tri[2]] || p[tri[0]] == p[tri[2]]) {
      keep[t] = false;
      any = true;
    }
  }
  if (!any && !look_for_sheets) return mesh;
  std::map<Position, std::uint32_t> first_at;
  std::vector<std::uint32_t> id;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    id.push_back(first_at.try_emplace(mesh.positions[v], static_cast<std::uint32_t>(v)).first->second);
  }
  std::map<std::array<std::uint32_t, 3>, std::array<std::vector<std::size_t>, 2>> by_key;
  for (std::size_t t = 0; t < before; ++t) {
    if (!keep[t]) continue;
    std::array<std::uint32_t, 3> k{id[mesh.triangles[t][0]], id[mesh.triangles[t][1]],
                                   id[mesh.triangles[t][2]]};
    std::rotate(k.begin(), std::min_element(k.begin(), k.end()), k.end());
    const int orientation = k[1] < k[2] ? 0 : 1;
    if (orientation == 1) std::swap(k[1], k[2]);
    by_key[k][orientation].push_back(t);
  }
  for (auto& [key, sides] : by_key) {
    for (std::size_t i = 0; i < std::min(sides[0].size(), sides[1].size()); ++i) {
      keep[sides[0][i]] = false;
      keep[sides[1][i]] = false;
    }
  }
  Mesh out = mesh;
  out.triangles.clear();
  out.face_kinds.clear();
  for (std::size_t t = 0; t < before; ++t) {
    if (!keep[t]) continue;
    out.triangles.push_back(mesh.triangles[t]);
    out.face_kinds.push_back(mesh.face_kinds[t]);
  }
  if (out.triangles.size() == before) return mesh;
  std::vector<std::uint32_t> remap(mesh.positions.size(), UINT32_MAX);
  for (const auto& t : out.triangles) {
    for (auto v : t) remap[v] = 0;
  }
  out.positions.clear();
  out.normals.clear();
  for (auto& a : out.attributes) a.clear();
  for (std::size_t v = 0; v < remap.size(); ++v) {
    if (remap[v] == UINT32_MAX) continue;
    remap[v] = static_cast<std::uint32_t>(out.positions.size());
    out.positions.push_back(mesh.positions[v]);
    out.normals.push_back(mesh.normals[v]);
    for (std::size_t a = 0; a < out.attributes.size(); ++a) out.attributes[a].push_back(mesh.attributes[a][v]);
  }
  for (auto& t : out.triangles) {
    for (auto& v : t) v = remap[v];
  }
  return out;
}

// Vertices on a 3 x 3 x 2 lattice (so many share a position), triangles drawn from
// them, and for some of them the opposite triangle over other vertices at the same
// positions, sometimes twice.
Mesh random_mesh(std::mt19937& rng, std::size_t vertices, std::size_t triangles) {
  Mesh m;
  std::uniform_int_distribution<int> coord(0, 2), pick(0, static_cast<int>(vertices) - 1), coin(0, 3);
  m.attribute_names = {"a"};
  m.attributes.resize(1);
  for (std::size_t v = 0; v < vertices; ++v) {
    m.positions.push_back({double(coord(rng)), double(coord(rng)), double(coord(rng) % 2)});
    m.normals.push_back({0, 0, float(v)});
    m.attributes[0].push_back(float(v) * 0.5f);
  }
  auto vertex_at = [&](const Position& p) {
    std::vector<std::uint32_t> at;
    for (std::uint32_t v = 0; v < vertices; ++v) {
      if (m.positions[v] == p) at.push_back(v);
    }
    return at[std::uniform_int_distribution<std::size_t>(0, at.size() - 1)(rng)];
  };
  while (m.triangles.size() < triangles) {
    const std::array<std::uint32_t, 3> t{std::uint32_t(pick(rng)), std::uint32_t(pick(rng)),
                                         std::uint32_t(pick(rng))};
    m.triangles.push_back(t);
    m.face_kinds.push_back(static_cast<FaceKind>(coin(rng)));
    for (int copies = coin(rng); copies > 1; --copies) {
      m.triangles.push_back({vertex_at(m.positions[t[2]]), vertex_at(m.positions[t[1]]),
                             vertex_at(m.positions[t[0]])});
      m.face_kinds.push_back(static_cast<FaceKind>(coin(rng)));
    }
  }
  return m;
}

TEST(CollapsedTriangles, MatchTheRuleOnRandomMeshesWithCoincidentPoints) {
  std::mt19937 rng(7);
  std::size_t removed_any = 0, kept_all = 0;
  for (int round = 0; round < 300; ++round) {
    const std::size_t vertices = 4 + static_cast<std::size_t>(round % 40);
    Mesh mesh = random_mesh(rng, vertices, 1 + static_cast<std::size_t>(round % 60));
    for (bool sheets : {false, true}) {
      const Mesh want = reference(mesh, sheets);
      Mesh got = mesh;
      const std::size_t removed = remove_collapsed_triangles(got, sheets);
      ASSERT_EQ(got, want) << "round " << round << " sheets " << sheets;
      EXPECT_EQ(removed, mesh.triangles.size() - want.triangles.size());
      (removed > 0 ? removed_any : kept_all) += 1;
    }
  }
  EXPECT_GT(removed_any, 100u);
  EXPECT_GT(kept_all, 10u);
}

TEST(CollapsedTriangles, OppositePairsGoFirstInOrderAndAnUnpairedOneStays) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}};
  m.normals.assign(4, {0, 0, 1});
  // Two triangles one way, one the other way (through vertex 3 at vertex 2's place).
  m.triangles = {{0, 1, 2}, {1, 2, 0}, {0, 3, 1}};
  m.face_kinds = {FaceKind::kLimit, FaceKind::kDomainBox, FaceKind::kNodeBoundary};
  EXPECT_EQ(remove_collapsed_triangles(m, true), 2u);
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.face_kinds[0], FaceKind::kDomainBox);
  EXPECT_EQ(m.positions.size(), 3u);  // vertex 3 unused, dropped
  const std::array<std::uint32_t, 3> rotated{1, 2, 0};
  EXPECT_EQ(m.triangles[0], rotated);
}

TEST(CollapsedTriangles, SheetsAreLookedForOnlyWhenAskedOrAfterASliver) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.normals.assign(3, {0, 0, 1});
  m.triangles = {{0, 1, 2}, {0, 2, 1}};
  m.face_kinds = {FaceKind::kLimit, FaceKind::kLimit};
  Mesh untouched = m;
  EXPECT_EQ(remove_collapsed_triangles(untouched, false), 0u);
  EXPECT_EQ(untouched, m);
  EXPECT_EQ(remove_collapsed_triangles(m, true), 2u);
  EXPECT_TRUE(m.triangles.empty());
  EXPECT_TRUE(m.positions.empty());
}

}  // namespace
}  // namespace strielad
