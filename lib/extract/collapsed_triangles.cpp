// SPDX-License-Identifier: Apache-2.0
#include "extract/collapsed_triangles.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
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
    // Opposite pairs over the same three positions: position ids, then per key (the
    // ids rotated smallest first, the other two ascending) how many triangles of each
    // orientation; of a key with both, the first min(count) of each in order go. Open
    // addressing in flat tables (this pass runs on every node where a crossing met a
    // sample, so it must cost about as much as the mesh, not a map node per triangle).
    constexpr std::uint32_t kEmpty = UINT32_MAX;
    const std::vector<std::uint32_t> id = first_vertex_at_each_position(mesh.positions);
    struct KeyCount {
      std::array<std::uint32_t, 3> key{kEmpty, kEmpty, kEmpty};
      std::array<std::uint32_t, 2> count{};
      std::array<std::uint32_t, 2> removed{};
    };
    const std::size_t key_cap = std::bit_ceil(std::max<std::size_t>(16, 2 * before));
    std::vector<KeyCount> keys(key_cap);
    std::vector<std::uint32_t> slot_of(before);
    std::vector<std::uint8_t> orientation_of(before);
    for (std::size_t t = 0; t < before; ++t) {
      if (!keep[t]) continue;
      std::array<std::uint32_t, 3> k{id[mesh.triangles[t][0]], id[mesh.triangles[t][1]],
                                     id[mesh.triangles[t][2]]};
      // Parity of the rotation to the smallest first, then whether the rest ascends.
      const auto first = std::min_element(k.begin(), k.end()) - k.begin();
      std::rotate(k.begin(), k.begin() + first, k.end());
      const int orientation = k[1] < k[2] ? 0 : 1;
      if (orientation == 1) std::swap(k[1], k[2]);
      std::size_t i = TripleHash{}(k) & (key_cap - 1);
      while (keys[i].key[0] != kEmpty && keys[i].key != k) i = (i + 1) & (key_cap - 1);
      keys[i].key = k;
      ++keys[i].count[orientation];
      slot_of[t] = static_cast<std::uint32_t>(i);
      orientation_of[t] = static_cast<std::uint8_t>(orientation);
    }
    for (std::size_t t = 0; t < before; ++t) {
      if (!keep[t]) continue;
      KeyCount& kc = keys[slot_of[t]];
      const std::uint32_t pairs = std::min(kc.count[0], kc.count[1]);
      std::uint32_t& removed = kc.removed[orientation_of[t]];
      if (removed < pairs) {
        ++removed;
        keep[t] = 0;
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
