// SPDX-License-Identifier: Apache-2.0
// Clips one tetrahedron of the sample lattice by half-space conditions whose values
// are linear inside it, leaving a convex polytope whose faces lie on the tetrahedron's
// faces or on the conditions' zero planes.
//
// Watertightness across tetrahedra rests on canonical vertices: a vertex on a lattice
// edge or lattice triangle is computed from the corners of that edge or triangle only,
// in ascending sample order, so every tetrahedron sharing it computes the same bits.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "extract/conditions.h"
#include "extract/mesh_builder.h"

namespace strielad {

// The point with barycentric weights w on the corners (in ascending sample order):
// the canonical sum, and a lattice face's coordinate kept exactly ((1-t)*10 + t*10
// need not round to 10), so every tetrahedron and every node sharing the point
// computes the same bits.
inline Vec3 lattice_point(const std::array<Vec3, 4>& corners, const std::array<double, 4>& w) {
  Vec3 p;
  for (int a = 0; a < 3; ++a) {
    double s = 0, lo = INFINITY, hi = -INFINITY;
    for (int k = 0; k < 4; ++k) {
      s += w[k] * corners[k][a];
      if (w[k] != 0.0) {
        lo = lo < corners[k][a] ? lo : corners[k][a];
        hi = hi > corners[k][a] ? hi : corners[k][a];
      }
    }
    p[a] = lo == hi ? lo : s;
  }
  return p;
}

// Where a condition with value sp at lattice corner P and sq at Q (one >= 0, the other
// < 0) crosses the lattice edge P-Q, P the lower sample (Q - P is 0 or 1 per axis):
// weights 1 - t and t with t = sp / (sp - sq), the point summed as lattice_point sums
// it (so the clipper's points on lattice triangles that land on the edge are the same
// bits). When rounding puts a coordinate on (or past) an end of the edge, the
// crossing is that corner exactly (t 0 or 1): a crossing is either a lattice corner or
// a point of its edge and of no other lattice element, so equal points are the same
// element. Every tetrahedron and every node sharing the edge computes the same bits.
// A crossing within kCrossingSnap of a cell from a corner is that corner too: with
// values of very different magnitude on one edge (1 next to 3e38: t = 3e-39) the point
// would be distinct on the lattice but not in axis coordinates, and the general clipper's
// points next to it would not meet the neighbouring tetrahedron's (a crack one 1e-39 of a
// cell wide). The surface moves by less than 1e-9 of a cell.
inline constexpr double kCrossingSnap = 0x1p-30;

struct EdgeCrossing {
  double t = 0;
  Vec3 p{};
};

// `corner_crossings` counts the crossings snapped onto a corner (a sample exactly on a
// bound, or within kCrossingSnap of one): only then can surfaces coincide (sheets
// without volume, collapsed_triangles.h), so the caller looks for them only when its
// count moved.
inline EdgeCrossing edge_crossing(const Vec3& P, const Vec3& Q, double sp, double sq,
                                  std::uint64_t& corner_crossings) {
  const double t = sp / (sp - sq);
  const double wp = 1.0 - t, wq = t;
  if (wq <= kCrossingSnap) {
    ++corner_crossings;
    return {0.0, P};
  }
  if (wp <= kCrossingSnap) {
    ++corner_crossings;
    return {1.0, Q};
  }
  bool at_p = false, at_q = false;
  // Per axis, in scalars (no partial writes to an array read back whole).
  auto coordinate = [&](double p, double q) {
    if (p == q) return p;
    double sum = 0;
    sum += wp * p;
    sum += wq * q;
    at_p = at_p || sum <= p;
    at_q = at_q || sum >= q;
    return sum;
  };
  const double x = coordinate(P[0], Q[0]);
  const double y = coordinate(P[1], Q[1]);
  const double z = coordinate(P[2], Q[2]);
  if (at_p) return {0.0, P};
  if (at_q) return {1.0, Q};
  return {t, Vec3{x, y, z}};
}

class TetClipper {
 public:
  struct Face {
    int tag = 0;  // 0..3: the tetrahedron face opposite that corner; 4 + c: condition c
    std::uint32_t first = 0, count = 0;  // range in loop()
  };

  // corners: sample ids in ascending order and their lattice positions; conditions:
  // bit c set = clip by condition c of `set`. Returns false when nothing is left.
  // Crossings put on a lattice corner are counted in `corner_crossings` (edge_crossing).
  bool clip(const std::array<std::size_t, 4>& corners, const std::array<Vec3, 4>& positions,
            const ConditionSet& set, std::uint64_t conditions, std::uint64_t& corner_crossings);

  const std::vector<Face>& faces() const { return faces_; }
  const std::vector<std::uint32_t>& loop() const { return loop_; }
  const Vec3& position(std::uint32_t vertex) const { return vertices_[vertex].p; }
  // Gradient (lattice units) of condition c inside the tetrahedron.
  Vec3 gradient(std::size_t c) const;
  // Gradient of the tetrahedron's barycentric coordinate of corner k.
  Vec3 barycentric_gradient(int k) const;

 private:
  struct Vertex {
    std::array<double, 4> w{};  // barycentric weights on the corners
    std::uint64_t planes = 0;   // bit k < 4: on the face opposite corner k; 4 + c: condition c
    Vec3 p{};
  };
  std::uint32_t add_vertex(const std::array<double, 4>& w, std::uint64_t planes);
  std::uint32_t add_vertex(const std::array<double, 4>& w, std::uint64_t planes, const Vec3& p);
  std::uint32_t crossing(std::uint32_t a, std::uint32_t b, std::size_t c,
                         std::uint64_t& corner_crossings);
  double value(std::uint32_t v, std::size_t c) const;
  bool clip_by(std::size_t c, std::uint64_t& corner_crossings);

  std::array<Vec3, 4> corner_pos_{};
  std::array<double, 4 * kMaxConditions> corner_values_{};  // [c * 4 + k]
  std::array<std::array<double, 3>, 3> inverse_edges_{};  // for gradients
  std::vector<Vertex> vertices_;
  std::vector<Face> faces_, next_faces_;
  std::vector<std::uint32_t> loop_, next_loop_;
  std::vector<double> vertex_values_;
  std::vector<std::array<std::uint32_t, 3>> crossings_;  // (a, b, new vertex) of one clip
  std::vector<std::uint32_t> cap_;
  std::vector<std::pair<double, std::uint32_t>> angle_order_;  // cap vertices by angle
};

}  // namespace strielad
