// SPDX-License-Identifier: Apache-2.0
#include "extract/collapsed_triangles.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

#include "extract/position_hash.h"

namespace strielad {
namespace {

using Position = std::array<double, 3>;

struct TripleHash {
  std::size_t operator()(const std::array<std::uint32_t, 3>& t) const noexcept {
    return (std::size_t{t[0]} * 0x9E3779B97F4A7C15ull) ^ (std::size_t{t[1]} * 0xC2B2AE3D27D4EB4Full) ^
           (std::size_t{t[2]} * 0x165667B19E3779F9ull);
  }
};

bool same(const Position& a, const Position& b) { return a == b; }

// Keeps the used vertices in their order.
void drop_unused_vertices(Mesh& mesh) {
  std::vector<std::uint32_t> remap(mesh.positions.size(), UINT32_MAX);
  for (const auto& t : mesh.triangles) {
    for (const auto v : t) remap[v] = 0;
  }
  std::uint32_t next = 0;
  for (auto& r : remap) {
    if (r != UINT32_MAX) r = next++;
  }
  for (auto& t : mesh.triangles) {
    for (auto& v : t) v = remap[v];
  }
  std::vector<Position> positions(next);
  std::vector<std::array<float, 3>> normals(next);
  std::vector<std::vector<float>> attributes(mesh.attributes.size(), std::vector<float>(next));
  for (std::size_t v = 0; v < remap.size(); ++v) {
    if (remap[v] == UINT32_MAX) continue;
    positions[remap[v]] = mesh.positions[v];
    normals[remap[v]] = mesh.normals[v];
    for (std::size_t a = 0; a < attributes.size(); ++a) attributes[a][remap[v]] = mesh.attributes[a][v];
  }
  mesh.positions = std::move(positions);
  mesh.normals = std::move(normals);
  mesh.attributes = std::move(attributes);
}

}  // namespace

std::size_t remove_collapsed_triangles(Mesh& mesh, bool look_for_sheets) {
  const std::size_t before = mesh.triangles.size();
  std::vector<std::uint8_t> keep(before, 1);
  bool any = false;
  for (std::size_t t = 0; t < before; ++t) {
    const auto& tri = mesh.triangles[t];
    const Position& a = mesh.positions[tri[0]];
    const Position& b = mesh.positions[tri[1]];
    const Position& c = mesh.positions[tri[2]];
    if (same(a, b) || same(b, c) || same(a, c)) {
      keep[t] = 0;
      any = true;
    }
  }
  if (!any && !look_for_sheets) return 0;
  {
    // Opposite pairs over the same three positions.
    std::unordered_map<Position, std::uint32_t, PositionBitsHash> ids;
    ids.reserve(mesh.positions.size());
    std::vector<std::uint32_t> id(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      id[v] = ids.try_emplace(mesh.positions[v], static_cast<std::uint32_t>(ids.size())).first->second;
    }
    // Key: the sorted position ids; value: triangles of each orientation, in order.
    std::unordered_map<std::array<std::uint32_t, 3>, std::array<std::vector<std::uint32_t>, 2>,
                       TripleHash>
        by_key;
    for (std::size_t t = 0; t < before; ++t) {
      if (!keep[t]) continue;
      std::array<std::uint32_t, 3> k{id[mesh.triangles[t][0]], id[mesh.triangles[t][1]],
                                     id[mesh.triangles[t][2]]};
      // Parity of the rotation to the smallest first, then whether the rest ascends.
      const auto first = std::min_element(k.begin(), k.end()) - k.begin();
      std::rotate(k.begin(), k.begin() + first, k.end());
      const int orientation = k[1] < k[2] ? 0 : 1;
      if (orientation == 1) std::swap(k[1], k[2]);
      by_key[k][orientation].push_back(static_cast<std::uint32_t>(t));
    }
    for (auto& [key, sides] : by_key) {
      const std::size_t pairs = std::min(sides[0].size(), sides[1].size());
      for (std::size_t i = 0; i < pairs; ++i) {
        keep[sides[0][i]] = 0;
        keep[sides[1][i]] = 0;
      }
    }
  }
  std::size_t kept = 0;
  for (std::size_t t = 0; t < before; ++t) {
    if (!keep[t]) continue;
    mesh.triangles[kept] = mesh.triangles[t];
    mesh.face_kinds[kept] = mesh.face_kinds[t];
    ++kept;
  }
  if (kept == before) return 0;
  mesh.triangles.resize(kept);
  mesh.face_kinds.resize(kept);
  drop_unused_vertices(mesh);
  return before - kept;
}

}  // namespace strielad
