// SPDX-License-Identifier: Apache-2.0
// Analytic fields on uneven axes for the peer tests (header only, shared by the tests in
// this folder).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <numbers>
#include <vector>

#include "extract/mesh.h"
#include "extract/node_samples.h"

namespace strielad::testing {

// n samples from lo to hi, spacing growing geometrically by `ratio` per cell (1 =
// uniform); descending when `descending`.
inline std::vector<double> stretched_axis(std::size_t n, double lo, double hi, double ratio,
                                          bool descending = false) {
  std::vector<double> steps(n - 1);
  double step = 1, total = 0;
  for (auto& s : steps) {
    s = step;
    total += step;
    step *= ratio;
  }
  std::vector<double> c(n);
  c[0] = lo;
  for (std::size_t i = 1; i < n; ++i) c[i] = c[i - 1] + (hi - lo) * steps[i - 1] / total;
  c[n - 1] = hi;
  if (descending) std::reverse(c.begin(), c.end());
  return c;
}

// Adds a field f(x, y, z) sampled on the lattice; returns its index.
inline std::size_t add_field(NodeSamples& s,
                             const std::function<double(double, double, double)>& f) {
  const auto d = s.dims();
  std::vector<float> values(s.sample_count());
  for (std::size_t k = 0; k < d[2]; ++k)
    for (std::size_t j = 0; j < d[1]; ++j)
      for (std::size_t i = 0; i < d[0]; ++i)
        values[(k * d[1] + j) * d[0] + i] =
            static_cast<float>(f(s.coords[0][i], s.coords[1][j], s.coords[2][k]));
  s.fields.push_back(std::move(values));
  return s.fields.size() - 1;
}

inline double distance(double x, double y, double z, const std::array<double, 3>& c) {
  return std::sqrt((x - c[0]) * (x - c[0]) + (y - c[1]) * (y - c[1]) + (z - c[2]) * (z - c[2]));
}

// A node with n samples per axis on [0, 1]^3: x stretched 1.08 per cell, y uniform and
// descending, z stretched 0.93 per cell (1:4 and 1:3 spacing ratios), and field 0 = the
// distance to `centre`.
inline NodeSamples sphere_node(std::size_t n, std::array<double, 3> centre = {0.5, 0.5, 0.5}) {
  NodeSamples s;
  s.coords[0] = stretched_axis(n, 0.0, 1.0, 1.08);
  s.coords[1] = stretched_axis(n, 0.0, 1.0, 1.0, /*descending=*/true);
  s.coords[2] = stretched_axis(n, 0.0, 1.0, 0.93);
  add_field(s, [&](double x, double y, double z) { return distance(x, y, z, centre); });
  return s;
}

inline double ball_volume(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

// Fraction of vertices of limit faces whose normal points away from `centre` (times
// `sign`).
inline double fraction_pointing_away(const Mesh& mesh, const std::array<double, 3>& centre,
                                     double sign = 1.0) {
  std::vector<bool> on_limit(mesh.vertex_count(), false);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (mesh.face_kinds[t] != FaceKind::kLimit) continue;
    for (auto v : mesh.triangles[t]) on_limit[v] = true;
  }
  std::size_t total = 0, away = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    if (!on_limit[v]) continue;
    ++total;
    double d = 0;
    for (int a = 0; a < 3; ++a) d += (mesh.positions[v][a] - centre[a]) * mesh.normals[v][a];
    if (sign * d > 0) ++away;
  }
  return total == 0 ? 0.0 : double(away) / double(total);
}

}  // namespace strielad::testing
