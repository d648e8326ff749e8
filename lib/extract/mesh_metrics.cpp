// SPDX-License-Identifier: Apache-2.0
#include "extract/mesh_metrics.h"

#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <unordered_map>
#include <vector>

#include "extract/position_hash.h"

namespace strielad {

namespace {

using P = std::array<double, 3>;

const P& d3(const P& p) { return p; }

}  // namespace

bool zero_area(const P& a, const P& b, const P& c) {
  const P e1{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const P e2{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  return e1[1] * e2[2] - e1[2] * e2[1] == 0 && e1[2] * e2[0] - e1[0] * e2[2] == 0 &&
         e1[0] * e2[1] - e1[1] * e2[0] == 0;
}

MeshCheck check_mesh(const Mesh& mesh) {
  MeshCheck check;
  std::unordered_map<P, std::uint32_t, PositionBitsHash> ids;
  std::vector<std::uint32_t> id_of(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const P& p = mesh.positions[v];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) ++check.bad_positions;
    id_of[v] = ids.try_emplace(p, static_cast<std::uint32_t>(ids.size())).first->second;
  }
  check.vertices = ids.size();
  for (const auto& n : mesh.normals) {
    const double len = std::sqrt(double{n[0]} * n[0] + double{n[1]} * n[1] + double{n[2]} * n[2]);
    if (!std::isfinite(len) || std::fabs(len - 1.0) > 1e-3) ++check.bad_normals;
  }
  // Directed edge counts keyed by (from, to).
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::array<std::uint32_t, 2>> edges;
  for (const auto& t : mesh.triangles) {
    const std::array<std::uint32_t, 3> v{id_of[t[0]], id_of[t[1]], id_of[t[2]]};
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2] ||
        zero_area(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]])) {
      ++check.degenerate_triangles;
    }
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t from = v[i], to = v[(i + 1) % 3];
      if (from == to) continue;
      auto& e = edges[{std::min(from, to), std::max(from, to)}];
      ++e[from < to ? 0 : 1];
    }
  }
  check.edges = edges.size();
  for (const auto& [key, count] : edges) {
    const std::uint32_t total = count[0] + count[1];
    if (total == 1) ++check.open_edges;
    else if (total > 2) ++check.nonmanifold_edges;
    else if (count[0] != 1) ++check.misoriented_edges;
  }
  return check;
}

double enclosed_volume(const Mesh& mesh) {
  if (mesh.positions.empty()) return 0.0;
  const auto o = d3(mesh.positions[0]);
  double six_v = 0;
  for (const auto& t : mesh.triangles) {
    std::array<std::array<double, 3>, 3> p;
    for (int i = 0; i < 3; ++i) {
      const auto q = d3(mesh.positions[t[i]]);
      p[i] = {q[0] - o[0], q[1] - o[1], q[2] - o[2]};
    }
    six_v += p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
             p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
             p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
  }
  return six_v / 6.0;
}

double surface_area(const Mesh& mesh) {
  double area = 0;
  for (const auto& t : mesh.triangles) {
    const auto a = d3(mesh.positions[t[0]]), b = d3(mesh.positions[t[1]]),
               c = d3(mesh.positions[t[2]]);
    const std::array<double, 3> e1{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const std::array<double, 3> e2{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double x = e1[1] * e2[2] - e1[2] * e2[1], y = e1[2] * e2[0] - e1[0] * e2[2],
                 z = e1[0] * e2[1] - e1[1] * e2[0];
    area += 0.5 * std::sqrt(x * x + y * y + z * z);
  }
  return area;
}

}  // namespace strielad
