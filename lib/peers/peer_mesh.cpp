// SPDX-License-Identifier: Apache-2.0
#include "peers/peer_mesh.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/vec3.h"

namespace strielad::peers {
namespace {

// Index of the cell of axis `axis` containing fractional index `index`, in [0, n-2].
std::size_t cell_of(const NodeSamples& samples, int axis, double index) {
  const std::size_t n = samples.coords[axis].size();
  if (!(index > 0)) return 0;  // also NaN
  return std::min(static_cast<std::size_t>(index), n - 2);
}

}  // namespace

EdgeCounts count_open_edges(const Mesh& mesh) {
  std::unordered_map<std::uint64_t, std::uint32_t> uses;
  uses.reserve(mesh.triangles.size() * 2);
  for (const auto& t : mesh.triangles) {
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = t[e], b = t[(e + 1) % 3];
      ++uses[(std::uint64_t(std::min(a, b)) << 32) | std::max(a, b)];
    }
  }
  EdgeCounts counts;
  for (const auto& [key, n] : uses) {
    if (n == 1) ++counts.boundary;
    if (n > 2) ++counts.non_manifold;
  }
  return counts;
}

void compute_vertex_normals(Mesh& mesh) {
  std::vector<Vec3> sums(mesh.positions.size(), Vec3{0, 0, 0});
  for (const auto& t : mesh.triangles) {
    const Vec3& p0 = mesh.positions[t[0]];
    // Unnormalised cross product: weighted by twice the triangle's area.
    const Vec3 n = cross(sub(mesh.positions[t[1]], p0), sub(mesh.positions[t[2]], p0));
    for (std::uint32_t v : t) {
      for (int a = 0; a < 3; ++a) sums[v][a] += n[a];
    }
  }
  mesh.normals.resize(mesh.positions.size());
  for (std::size_t v = 0; v < sums.size(); ++v) {
    const double len = length(sums[v]);
    if (len > 0 && std::isfinite(len)) {
      mesh.normals[v] = {float(sums[v][0] / len), float(sums[v][1] / len), float(sums[v][2] / len)};
    } else {
      mesh.normals[v] = {0.0f, 0.0f, 1.0f};
    }
  }
}

double index_to_axis(const NodeSamples& samples, int axis, double index) {
  const auto& c = samples.coords[axis];
  const std::size_t i = cell_of(samples, axis, index);
  return c[i] + (index - double(i)) * (c[i + 1] - c[i]);
}

double axis_spacing_at(const NodeSamples& samples, int axis, double index) {
  const auto& c = samples.coords[axis];
  const std::size_t i = cell_of(samples, axis, index);
  return c[i + 1] - c[i];
}

void map_index_mesh_to_axes(Mesh& mesh, const NodeSamples& samples) {
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    auto& p = mesh.positions[v];
    Vec3 spacing{};
    for (int a = 0; a < 3; ++a) {
      spacing[a] = axis_spacing_at(samples, a, p[a]);
      p[a] = index_to_axis(samples, a, p[a]);
    }
    if (v < mesh.normals.size()) {
      auto& n = mesh.normals[v];
      const Vec3 m{n[0] / spacing[0], n[1] / spacing[1], n[2] / spacing[2]};
      const double len = length(m);
      if (len > 0 && std::isfinite(len)) {
        n = {float(m[0] / len), float(m[1] / len), float(m[2] / len)};
      }
    }
  }
  int descending = 0;
  for (int a = 0; a < 3; ++a) {
    if (samples.coords[a].size() >= 2 && samples.coords[a][1] < samples.coords[a][0]) ++descending;
  }
  if (descending % 2 == 1) {
    for (auto& t : mesh.triangles) std::swap(t[1], t[2]);
  }
}

}  // namespace strielad::peers
