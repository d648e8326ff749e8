// SPDX-License-Identifier: Apache-2.0
#include "extract/cell_tables.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <utility>

#include "core/error.h"
#include "core/vec3.h"

namespace strielad {

namespace {

// Cube corner k's position in the unit cell.
Vec3 corner_position(int k) { return Vec3{double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)}; }

// Newell's normal of the polygon pts[0..m).
Vec3 newell_normal(const Vec3* pts, int m) {
  Vec3 n{0, 0, 0};
  for (int i = 0; i < m; ++i) {
    const Vec3& a = pts[i];
    const Vec3& b = pts[(i + 1) % m];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return n;
}

// The 19 Kuhn edges, numbered by ascending (p, q).
void number_kuhn_edges(CellTables& t) {
  for (auto& row : t.edge_index) row.fill(-1);
  int e = 0;
  for (int p = 0; p < 8; ++p) {
    for (int q = p + 1; q < 8; ++q) {
      if ((p & q) != p) continue;
      t.edges[e] = {p, q};
      t.edge_index[p][q] = e++;
    }
  }
}

// The corner pairs (tetrahedron corners 0..3) whose edges the plane crosses when the
// corners `in` are inside, in a cyclic order (either turn).
int crossed_tet_edges(int in, std::array<std::pair<int, int>, 4>& pairs) {
  int count = 0;
  const int n_in = std::popcount(static_cast<unsigned>(in));
  if (n_in == 1 || n_in == 3) {
    const int lone = std::countr_zero(static_cast<unsigned>(n_in == 1 ? in : ~in & 15));
    for (int k = 0; k < 4; ++k) {
      if (k != lone) pairs[count++] = {std::min(k, lone), std::max(k, lone)};
    }
  } else {
    int a = -1, b = -1, c = -1, d = -1;
    for (int k = 0; k < 4; ++k) {
      if (in & (1 << k)) (a < 0 ? a : b) = k;
      else (c < 0 ? c : d) = k;
    }
    for (const auto& [u, v] : {std::pair{a, c}, {a, d}, {b, d}, {b, c}}) {
      pairs[count++] = {std::min(u, v), std::max(u, v)};
    }
  }
  return count;
}

// Tetrahedron t's polygon for the inside corners `in` (1..14), turned outward.
void build_tet_polygon(CellTables& t, int tet_index, int in) {
  const auto& tet = kTets[tet_index];
  TetPolygon& poly = t.polygons[tet_index][in];
  std::array<std::pair<int, int>, 4> pairs{};
  poly.count = crossed_tet_edges(in, pairs);
  const int n_in = std::popcount(static_cast<unsigned>(in));
  // Orientation: the normal points from the inside corners to the outside ones
  // (the polygon through the edge midpoints turns the same way as through any
  // crossings inside the edges).
  Vec3 mid[4];
  Vec3 dir{0, 0, 0};  // centroid of the outside corners - centroid of the inside ones
  for (int k = 0; k < 4; ++k) {
    const Vec3 p = corner_position(tet[k]);
    const double w = (in >> k) & 1 ? -1.0 / n_in : 1.0 / (4 - n_in);
    for (int a = 0; a < 3; ++a) dir[a] += w * p[a];
  }
  for (int i = 0; i < poly.count; ++i) {
    const Vec3 p = corner_position(tet[pairs[i].first]), q = corner_position(tet[pairs[i].second]);
    for (int a = 0; a < 3; ++a) mid[i][a] = (p[a] + q[a]) / 2;
    poly.edges[i] = t.edge_index[tet[pairs[i].first]][tet[pairs[i].second]];
  }
  if (dot(newell_normal(mid, poly.count), dir) < 0) {
    std::reverse(poly.edges.begin(), poly.edges.begin() + poly.count);
  }
}

// Tetrahedron t's face opposite corner `opposite`: its cell side, if any, and turn.
void build_tet_face(CellTables& t, int tet_index, int opposite) {
  const auto& tet = kTets[tet_index];
  TetFace& f = t.faces[tet_index][opposite];
  int and_bits = 7, or_bits = 0;
  for (int k = 0, j = 0; k < 4; ++k) {
    if (k == opposite) continue;
    and_bits &= tet[k];
    or_bits |= tet[k];
    f.local[j] = k;
    f.corners[j++] = tet[k];
  }
  for (int a = 0; a < 3 && f.side < 0; ++a) {
    if (!(or_bits & (1 << a))) f.side = 2 * a;
    if (and_bits & (1 << a)) f.side = 2 * a + 1;
  }
  if (f.side < 0) return;
  Vec3 p[3];
  for (int j = 0; j < 3; ++j) p[j] = corner_position(f.corners[j]);
  const Vec3 n = cross(sub(p[1], p[0]), sub(p[2], p[0]));
  const double out = f.side % 2 == 0 ? -1.0 : 1.0;
  f.reversed = n[f.side / 2] * out < 0;
}

void build_side_quads(CellTables& t) {
  for (int a = 0; a < 3; ++a) {
    const int u = 1 << ((a + 1) % 3), v = 1 << ((a + 2) % 3);
    for (int side = 0; side < 2; ++side) {
      const int o = side == 0 ? 0 : (1 << a);
      auto& quad = t.side_quads[2 * a + side];
      quad = {o, o | u, o | u | v, o | v};  // normal +axis
      if (side == 0) std::swap(quad[1], quad[3]);
    }
  }
}

// Per side: the region's boundary on the side's two Kuhn triangles (outward order),
// each entry crossing linked to the next exit crossing turned around (the surface runs
// each shared edge the other way); on an unsplit side the two pieces through the
// diagonal become one. next[e]: the Kuhn edge after e on its loop, -1 if none.
std::array<int, 19> link_side_crossings(const CellTables& t, int in, int split) {
  std::array<int, 19> next{};
  next.fill(-1);
  for (int side = 0; side < 6; ++side) {
    const auto& q = t.side_quads[side];
    const int diagonal = t.edge_index[q[0]][q[2]];
    int into_diagonal = -1, from_diagonal = -1;
    for (const std::array<int, 3>& tri : CellTables::side_triangles(q)) {
      int entry = -1, exit = -1;
      for (int i = 0; i < 3; ++i) {
        const int cur = tri[i], nxt = tri[(i + 1) % 3];
        const bool cin = (in >> cur) & 1, nin = (in >> nxt) & 1;
        if (cin == nin) continue;
        (cin ? exit : entry) = t.edge_index[std::min(cur, nxt)][std::max(cur, nxt)];
      }
      if (entry < 0) continue;
      if (next[entry] >= 0) {
        throw make_error(ErrorCode::kInternal, "cell loop table: two edges leave one crossing");
      }
      next[entry] = exit;
      if (exit == diagonal) into_diagonal = entry;
      if (entry == diagonal) from_diagonal = exit;
    }
    if (!((split >> side) & 1) && into_diagonal >= 0) {
      next[into_diagonal] = from_diagonal;
      next[diagonal] = -1;
    }
  }
  return next;
}

// The loops of one entry: the linked crossings followed round, each loop starting at
// its first diagonal crossing.
void build_cell_loops(CellTables& t, int in, int split) {
  const std::array<int, 19> next = link_side_crossings(t, in, split);
  CellLoops& out = t.loops[static_cast<std::size_t>(in) * 64 + static_cast<std::size_t>(split)];
  std::array<bool, 19> seen{};
  int written = 0;
  for (int start = 0; start < 19; ++start) {
    if (next[start] < 0 || seen[start]) continue;
    std::array<int, 18> loop{};
    int n = 0, first = -1;
    int e = start;
    do {
      if (e < 0 || seen[e] || n == 18) {
        throw make_error(ErrorCode::kInternal, "cell loop table: a loop that does not close");
      }
      seen[e] = true;
      const bool on_diagonal = std::popcount(static_cast<unsigned>(t.edges[e].p ^ t.edges[e].q)) == 2;
      if (on_diagonal && first < 0) first = n;
      loop[n++] = e;
      e = next[e];
    } while (e != start);
    if (first < 0) first = 0;
    if (out.loops == out.size.size() || n < 3) {
      throw make_error(ErrorCode::kInternal, "cell loop table: too many loops or a loop of two");
    }
    out.size[out.loops++] = static_cast<std::uint8_t>(n);
    for (int i = 0; i < n; ++i) out.edges[written++] = static_cast<std::uint8_t>(loop[(first + i) % n]);
  }
}

// Per inside pattern: the sides it crosses, and its loops for every choice of split sides.
void build_marching_table(CellTables& t) {
  for (int in = 1; in < 255; ++in) {
    for (int side = 0; side < 6; ++side) {
      int count = 0;
      for (int k : t.side_quads[side]) count += (in >> k) & 1;
      if (count != 0 && count != 4) t.crossed_sides[in] |= static_cast<std::uint8_t>(1 << side);
    }
    for (int split = 0; split < 64; ++split) build_cell_loops(t, in, split);
  }
}

}  // namespace

CellTables::CellTables() {
  number_kuhn_edges(*this);
  for (int t = 0; t < 6; ++t) {
    for (int in = 1; in < 15; ++in) build_tet_polygon(*this, t, in);
    for (int opposite = 0; opposite < 4; ++opposite) build_tet_face(*this, t, opposite);
  }
  build_side_quads(*this);
  build_marching_table(*this);
}

}  // namespace strielad
