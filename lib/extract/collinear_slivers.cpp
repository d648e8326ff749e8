// SPDX-License-Identifier: Apache-2.0
#include "extract/collinear_slivers.h"

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "extract/mesh_metrics.h"
#include "extract/position_hash.h"

namespace strielad {
namespace {

using Position = std::array<double, 3>;

// At most this many rounds: each splits every sliver whose neighbour is not a sliver,
// so chains of slivers along one line resolve from their ends.
constexpr int kMaxRounds = 16;

Position minus(const Position& a, const Position& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

std::uint64_t edge_key(std::uint32_t from, std::uint32_t to) {
  return (std::uint64_t{from} << 32) | to;
}

class SliverSplitter {
 public:
  explicit SliverSplitter(Mesh& mesh)
      : mesh_(mesh), position_id_(first_vertex_at_each_position(mesh.positions)) {}

  // One round; returns the slivers removed.
  std::size_t round() {
    const std::size_t n = mesh_.triangles.size();
    std::vector<std::uint8_t> sliver(n, 0);
    bool any = false;
    for (std::size_t t = 0; t < n; ++t) {
      sliver[t] = is_sliver(t) ? 1 : 0;
      any = any || sliver[t];
    }
    if (!any) return 0;
    // Directed edges between positions: the triangle holding each (kShared if several).
    std::unordered_map<std::uint64_t, std::uint32_t> edge_owner;
    for (std::size_t t = 0; t < n; ++t) {
      for (int i = 0; i < 3; ++i) {
        const auto key = edge_key(pid(t, i), pid(t, (i + 1) % 3));
        const auto [it, fresh] = edge_owner.try_emplace(key, static_cast<std::uint32_t>(t));
        if (!fresh) it->second = kShared;
      }
    }
    std::vector<std::uint8_t> touched(n, 0), removed(n, 0);
    std::size_t count = 0;
    for (std::size_t t = 0; t < n; ++t) {
      if (!sliver[t] || touched[t]) continue;
      const int k = middle(t);
      if (k < 0) continue;
      // The long edge runs from vertex k + 1 to k + 2; the neighbour holds it reversed.
      const auto& tri = mesh_.triangles[t];
      const std::uint32_t from = pid(t, (k + 1) % 3), to = pid(t, (k + 2) % 3);
      const auto it = edge_owner.find(edge_key(to, from));
      if (it == edge_owner.end() || it->second == kShared) continue;
      const std::uint32_t nb = it->second;
      if (nb == t || sliver[nb] || touched[nb]) continue;
      int j = 0;
      while (!(pid(nb, j) == to && pid(nb, (j + 1) % 3) == from)) ++j;
      const auto neighbour = mesh_.triangles[nb];
      const std::uint32_t a = neighbour[j], c = neighbour[(j + 1) % 3], d = neighbour[(j + 2) % 3];
      const std::uint32_t m = tri[k];
      mesh_.triangles[nb] = {a, m, d};
      mesh_.triangles.push_back({m, c, d});
      mesh_.face_kinds.push_back(mesh_.face_kinds[nb]);
      touched[nb] = 1;
      touched[t] = 1;
      removed[t] = 1;
      ++count;
    }
    std::size_t kept = 0;
    for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
      if (t < n && removed[t]) continue;
      mesh_.triangles[kept] = mesh_.triangles[t];
      mesh_.face_kinds[kept] = mesh_.face_kinds[t];
      ++kept;
    }
    mesh_.triangles.resize(kept);
    mesh_.face_kinds.resize(kept);
    return count;
  }

 private:
  static constexpr std::uint32_t kShared = UINT32_MAX;

  std::uint32_t pid(std::size_t t, int i) const { return position_id_[mesh_.triangles[t][i]]; }

  bool is_sliver(std::size_t t) const {
    const auto& tri = mesh_.triangles[t];
    const auto& p = mesh_.positions;
    if (pid(t, 0) == pid(t, 1) || pid(t, 1) == pid(t, 2) || pid(t, 0) == pid(t, 2)) return false;
    return zero_area(p[tri[0]], p[tri[1]], p[tri[2]]);
  }

  // The corner of sliver t between the other two (its edges to them point apart), or -1.
  int middle(std::size_t t) const {
    const auto& tri = mesh_.triangles[t];
    const auto& p = mesh_.positions;
    for (int k = 0; k < 3; ++k) {
      const Position& m = p[tri[k]];
      const Position u = minus(p[tri[(k + 1) % 3]], m), w = minus(p[tri[(k + 2) % 3]], m);
      if (u[0] * w[0] + u[1] * w[1] + u[2] * w[2] < 0) return k;
    }
    return -1;
  }

  Mesh& mesh_;
  std::vector<std::uint32_t> position_id_;
};

}  // namespace

std::size_t split_collinear_slivers(Mesh& mesh) {
  SliverSplitter splitter(mesh);
  std::size_t total = 0;
  for (int r = 0; r < kMaxRounds; ++r) {
    const std::size_t removed = splitter.round();
    if (removed == 0) break;
    total += removed;
  }
  return total;
}

}  // namespace strielad
