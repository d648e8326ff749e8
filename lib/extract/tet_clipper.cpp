// SPDX-License-Identifier: Apache-2.0
#include "extract/tet_clipper.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace strielad {

namespace {


}  // namespace

std::uint32_t TetClipper::add_vertex(const std::array<double, 4>& w, std::uint64_t planes) {
  // Canonical sum: corners in ascending sample order, zero weights add exact zeros.
  return add_vertex(w, planes, lattice_point(corner_pos_, w));
}

std::uint32_t TetClipper::add_vertex(const std::array<double, 4>& w, std::uint64_t planes,
                                     const Vec3& p) {
  Vertex v;
  v.w = w;
  v.planes = planes;
  for (int k = 0; k < 4; ++k) {
    if (w[k] == 0.0) v.planes |= std::uint64_t{1} << k;
  }
  v.p = p;
  vertices_.push_back(v);
  return static_cast<std::uint32_t>(vertices_.size() - 1);
}

double TetClipper::value(std::uint32_t v, std::size_t c) const {
  const auto& w = vertices_[v].w;
  const double* s = &corner_values_[c * 4];
  double sum = 0;
  for (int k = 0; k < 4; ++k) sum += w[k] * s[k];
  return sum;
}

// The point where condition c crosses the polytope edge a-b (value(a) >= 0 > value(b)
// or the reverse).
std::uint32_t TetClipper::crossing(std::uint32_t a, std::uint32_t b, std::size_t c,
                                   std::uint64_t& corner_crossings) {
  const Vertex& va = vertices_[a];
  const Vertex& vb = vertices_[b];
  const std::uint64_t common = va.planes & vb.planes;
  const std::uint64_t new_plane = std::uint64_t{1} << (4 + c);
  const std::uint64_t face_bits = common & 0xF;
  constexpr int kBits4[16]{0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
  const int faces_shared = kBits4[face_bits];
  const double* s = &corner_values_[c * 4];
  std::array<double, 4> w{};
  if (faces_shared >= 2) {
    // On a lattice edge: from that edge's two corners (lower sample first).
    int p = -1, q = -1;
    for (int k = 0; k < 4; ++k) {
      if (face_bits & (std::uint64_t{1} << k)) continue;
      (p < 0 ? p : q) = k;
    }
    if (faces_shared == 2 && s[p] != s[q] && (s[p] >= 0) != (s[q] >= 0)) {
      // The same point as the kernel's marching tetrahedra make on this edge.
      const EdgeCrossing x = edge_crossing(corner_pos_[p], corner_pos_[q], s[p], s[q], corner_crossings);
      w[p] = 1.0 - x.t;
      w[q] = x.t;
      return add_vertex(w, common | new_plane, x.p);
    }
  } else if (faces_shared == 1) {
    // On a lattice triangle, where this condition meets an earlier one.
    const std::uint64_t condition_bits = common >> 4;
    if (condition_bits != 0 && (condition_bits & (condition_bits - 1)) == 0) {
      const std::size_t c1 = static_cast<std::size_t>(std::countr_zero(condition_bits));
      const std::size_t u1 = std::min(c1, c), u2 = std::max(c1, c);
      const int face = std::countr_zero(face_bits);
      std::array<int, 3> k{};
      for (int i = 0, j = 0; i < 4; ++i) {
        if (i != face) k[j++] = i;
      }
      const double* s1 = &corner_values_[u1 * 4];
      const double* s2 = &corner_values_[u2 * 4];
      // A condition that is zero at two corners of the triangle (a box bound on a
      // sample plane, a limit equal to two samples) has the lattice edge between them as
      // its zero line there: the meeting point is the other condition's crossing on that
      // edge, computed as every cell sharing the edge computes it (solving the system
      // below gives the same point up to rounding, which would open a crack).
      for (const auto& [zero, other] : {std::pair{s1, s2}, std::pair{s2, s1}}) {
        for (int i = 0; i < 3; ++i) {
          const int p = k[i == 2 ? 0 : i], q = k[i == 2 ? 2 : i + 1], r = k[i == 0 ? 2 : i == 1 ? 0 : 1];
          if (zero[p] != 0.0 || zero[q] != 0.0 || zero[r] == 0.0) continue;
          if ((other[p] >= 0) == (other[q] >= 0)) continue;
          const EdgeCrossing x = edge_crossing(corner_pos_[p], corner_pos_[q], other[p], other[q],
                                               corner_crossings);
          w[p] = 1.0 - x.t;
          w[q] = x.t;
          return add_vertex(w, common | new_plane, x.p);
        }
      }
      const double a11 = s1[k[1]] - s1[k[0]], a12 = s1[k[2]] - s1[k[0]], b1 = -s1[k[0]];
      const double a21 = s2[k[1]] - s2[k[0]], a22 = s2[k[2]] - s2[k[0]], b2 = -s2[k[0]];
      const double det = a11 * a22 - a12 * a21;
      if (det != 0.0 && std::isfinite(det)) {
        const double wb = (b1 * a22 - a12 * b2) / det;
        const double wc = (a11 * b2 - b1 * a21) / det;
        const double wa = 1.0 - wb - wc;
        constexpr double kSlack = 1e-9;
        if (wa >= -kSlack && wb >= -kSlack && wc >= -kSlack && std::isfinite(wa) &&
            std::isfinite(wb) && std::isfinite(wc)) {
          w[k[0]] = std::max(wa, 0.0);
          w[k[1]] = std::max(wb, 0.0);
          w[k[2]] = std::max(wc, 0.0);
          const double sum = w[k[0]] + w[k[1]] + w[k[2]];
          for (int i : k) w[i] /= sum;
          return add_vertex(w, common | new_plane);
        }
      }
    }
  }
  // Inside the tetrahedron (not shared) or a degenerate case: along the edge itself.
  const double sa = value(a, c), sb = value(b, c);
  const double t = sa == sb ? 0.0 : std::clamp(sa / (sa - sb), 0.0, 1.0);
  for (int k = 0; k < 4; ++k) w[k] = va.w[k] + t * (vb.w[k] - va.w[k]);
  return add_vertex(w, common | new_plane);
}

bool TetClipper::clip_by(std::size_t c, std::uint64_t& corner_crossings) {
  vertex_values_.resize(vertices_.size());
  bool any_in = false, any_out = false;
  for (std::uint32_t v = 0; v < vertices_.size(); ++v) {
    vertex_values_[v] = value(v, c);
  }
  for (std::uint32_t v : loop_) {
    const bool in = vertex_values_[v] >= 0;
    any_in = any_in || in;
    any_out = any_out || !in;
  }
  if (!any_in) return false;
  if (!any_out) return true;

  crossings_.clear();
  next_faces_.clear();
  next_loop_.clear();
  auto crossing_of = [&](std::uint32_t a, std::uint32_t b) {
    const std::uint32_t lo = std::min(a, b), hi = std::max(a, b);
    for (const auto& x : crossings_) {
      if (x[0] == lo && x[1] == hi) return x[2];
    }
    const std::uint32_t v = crossing(lo, hi, c, corner_crossings);
    crossings_.push_back({lo, hi, v});
    return v;
  };
  for (const Face& face : faces_) {
    Face out{face.tag, static_cast<std::uint32_t>(next_loop_.size()), 0};
    for (std::uint32_t i = 0; i < face.count; ++i) {
      const std::uint32_t cur = loop_[face.first + i];
      const std::uint32_t nxt = loop_[face.first + (i + 1) % face.count];
      const bool cin = vertex_values_[cur] >= 0;
      const bool nin = vertex_values_[nxt] >= 0;
      if (cin) next_loop_.push_back(cur);
      if (cin != nin) next_loop_.push_back(crossing_of(cur, nxt));
    }
    out.count = static_cast<std::uint32_t>(next_loop_.size()) - out.first;
    if (out.count >= 3) {
      next_faces_.push_back(out);
    } else {
      next_loop_.resize(out.first);
    }
  }
  // The cap: the crossings, distinct positions, ordered by angle in the plane.
  cap_.clear();
  for (const auto& x : crossings_) {
    const Vec3& p = vertices_[x[2]].p;
    bool seen = false;
    for (std::uint32_t v : cap_) seen = seen || vertices_[v].p == p;
    if (!seen) cap_.push_back(x[2]);
  }
  if (cap_.size() >= 3) {
    Vec3 n = gradient(c);
    const double len = std::sqrt(dot(n, n));
    if (len > 0 && std::isfinite(len)) {
      for (double& x : n) x /= len;  // scale-free: condition values may be 1e-30 or 1e30
      Vec3 centre{0, 0, 0};
      for (std::uint32_t v : cap_) {
        for (int a = 0; a < 3; ++a) centre[a] += vertices_[v].p[a] / static_cast<double>(cap_.size());
      }
      const Vec3 helper = std::fabs(n[0]) < 0.5 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
      const Vec3 u = cross(n, helper);
      const Vec3 w = cross(n, u);
      auto& order = angle_order_;
      order.clear();
      for (std::uint32_t v : cap_) {
        const Vec3 d = sub(vertices_[v].p, centre);
        order.emplace_back(std::atan2(dot(d, w), dot(d, u)), v);
      }
      std::sort(order.begin(), order.end());
      Face cap{static_cast<int>(4 + c), static_cast<std::uint32_t>(next_loop_.size()),
               static_cast<std::uint32_t>(order.size())};
      for (const auto& [angle, v] : order) next_loop_.push_back(v);
      next_faces_.push_back(cap);
    }
  }
  faces_.swap(next_faces_);
  loop_.swap(next_loop_);
  return !faces_.empty();
}

Vec3 TetClipper::gradient(std::size_t c) const {
  const double* s = &corner_values_[c * 4];
  const Vec3 ds{s[1] - s[0], s[2] - s[0], s[3] - s[0]};
  Vec3 g{};
  for (int a = 0; a < 3; ++a) g[a] = dot(inverse_edges_[a], ds);
  return g;
}

Vec3 TetClipper::barycentric_gradient(int k) const {
  Vec3 ds{0, 0, 0};
  if (k == 0) {
    ds = {-1, -1, -1};
  } else {
    ds[k - 1] = 1;
  }
  Vec3 g{};
  for (int a = 0; a < 3; ++a) g[a] = dot(inverse_edges_[a], ds);
  return g;
}

bool TetClipper::clip(const std::array<std::size_t, 4>& corners,
                      const std::array<Vec3, 4>& positions, const ConditionSet& set,
                      std::uint64_t conditions, std::uint64_t& corner_crossings) {
  corner_pos_ = positions;
  for (std::uint64_t bits = conditions; bits != 0; bits &= bits - 1) {
    const std::size_t c = static_cast<std::size_t>(std::countr_zero(bits));
    const Condition& condition = set.conditions[c];
    for (int k = 0; k < 4; ++k) corner_values_[c * 4 + k] = condition.value(corners[k]);
  }
  // Inverse of the edge matrix E (rows P1-P0, P2-P0, P3-P0): gradient = E^-1 ds.
  const Vec3 e1 = sub(positions[1], positions[0]);
  const Vec3 e2 = sub(positions[2], positions[0]);
  const Vec3 e3 = sub(positions[3], positions[0]);
  const Vec3 c23 = cross(e2, e3), c31 = cross(e3, e1), c12 = cross(e1, e2);
  const double det = dot(e1, c23);
  // Columns of E^-1 are c23/det, c31/det, c12/det; store rows for dot products.
  for (int a = 0; a < 3; ++a) {
    inverse_edges_[a] = {c23[a] / det, c31[a] / det, c12[a] / det};
  }

  vertices_.clear();
  faces_.clear();
  loop_.clear();
  for (int k = 0; k < 4; ++k) {
    std::array<double, 4> w{};
    w[k] = 1.0;
    add_vertex(w, 0);
  }
  // Faces opposite each corner, oriented later by the caller.
  static constexpr std::array<std::array<std::uint32_t, 3>, 4> kFaces{
      {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}}};
  for (int k = 0; k < 4; ++k) {
    faces_.push_back(Face{k, static_cast<std::uint32_t>(loop_.size()), 3});
    for (std::uint32_t v : kFaces[k]) loop_.push_back(v);
  }
  for (std::uint64_t bits = conditions; bits != 0; bits &= bits - 1) {
    if (!clip_by(static_cast<std::size_t>(std::countr_zero(bits)), corner_crossings)) return false;
  }
  return true;
}

}  // namespace strielad
