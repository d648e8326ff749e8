// SPDX-License-Identifier: Apache-2.0
#include "extract/node_extractor.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <type_traits>

#include "core/error.h"
#include "extract/collapsed_triangles.h"
#include "extract/collinear_slivers.h"
#include "extract/conditions.h"
#include "extract/mesh_builder.h"
#include "extract/tet_clipper.h"

namespace strielad {

namespace {

// The six Kuhn tetrahedra of a cell: corners as cube indices (bit 0 x, 1 y, 2 z), in
// ascending order, which is also ascending sample order.
constexpr std::array<std::array<int, 4>, 6> kTets{{{0, 1, 3, 7},
                                                   {0, 1, 5, 7},
                                                   {0, 2, 3, 7},
                                                   {0, 2, 6, 7},
                                                   {0, 4, 5, 7},
                                                   {0, 4, 6, 7}}};

// Node and cell sides are numbered 2 * axis + side (side 1 the upper face).
//
// The lattice edges of a cell the Kuhn split uses: corner pairs p < q with q's bits a
// superset of p's (12 cell edges, 6 face diagonals, the main diagonal).
struct CellEdge {
  int p = 0, q = 0;
};

// A tetrahedron's polygon on a condition's zero plane for one in/out pattern of its
// corners: cell edges in outward (counter-clockwise seen from outside) order.
struct TetPolygon {
  int count = 0;
  std::array<int, 4> edges{};
};

// The limit surface of a cell crossed by one condition, for one in/out pattern of its
// corners and one choice of split sides: closed loops of Kuhn edges, each turning
// outward (counter-clockwise seen from outside the region). A loop meets every side the
// condition crosses along the side's own crossings: on a split side through the
// crossing on its min-max diagonal, as the Kuhn tetrahedra of the cell beyond meet it
// (a cell crossed by several conditions, or the node beyond the node's boundary); on
// any other side straight from cell edge to cell edge, as the same table meets it from
// the neighbouring cell. On an unsplit side whose four corners alternate, the corners
// on the min-max diagonal are the ones joined, as on a split side. A loop through a
// diagonal crossing starts there (a fan from it never makes a triangle of three points
// on one side, which are collinear where the field is linear).
struct CellLoops {
  std::uint8_t loops = 0;
  std::array<std::uint8_t, 6> size{};
  std::array<std::uint8_t, 18> edges{};
};

// A tetrahedron face on a cell side: its corners in ascending order, and whether that
// order turns inward (clockwise seen from outside).
struct TetFace {
  int side = -1;  // 2 * axis + side, or -1 when the face is inside the cell
  std::array<int, 3> corners{};  // cell corners
  std::array<int, 3> local{};    // the same as corners of the tetrahedron (0..3)
  bool reversed = false;
};

struct Tables {
  std::array<CellEdge, 19> edges{};
  std::array<std::array<int, 8>, 8> edge_index{};  // [p][q], -1 if not a Kuhn edge
  std::array<std::array<TetPolygon, 16>, 6> polygons{};  // [tet][inside bits of its corners]
  std::array<std::array<TetFace, 4>, 6> faces{};          // [tet][opposite corner]
  // Cell faces on each side: corners in outward order, the first and third on the
  // face's min-max diagonal, so that the triangles (0, 1, 2) and (0, 2, 3) split it as
  // the Kuhn tetrahedra do.
  std::array<std::array<int, 4>, 6> side_quads{};
  std::array<CellLoops, 256 * 64> loops{};  // [inside bits * 64 + split sides]
  std::array<std::uint8_t, 256> crossed_sides{};  // [inside bits]: sides whose corners differ

  Tables() {
    auto pos = [](int k) { return Vec3{double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)}; };
    for (auto& row : edge_index) row.fill(-1);
    int e = 0;
    for (int p = 0; p < 8; ++p) {
      for (int q = p + 1; q < 8; ++q) {
        if ((p & q) != p) continue;
        edges[e] = {p, q};
        edge_index[p][q] = e++;
      }
    }
    auto newell = [](const Vec3* pts, int m) {
      Vec3 n{0, 0, 0};
      for (int i = 0; i < m; ++i) {
        const Vec3& a = pts[i];
        const Vec3& b = pts[(i + 1) % m];
        n[0] += (a[1] - b[1]) * (a[2] + b[2]);
        n[1] += (a[2] - b[2]) * (a[0] + b[0]);
        n[2] += (a[0] - b[0]) * (a[1] + b[1]);
      }
      return n;
    };
    for (int t = 0; t < 6; ++t) {
      const auto& tet = kTets[t];
      for (int in = 1; in < 15; ++in) {
        TetPolygon& poly = polygons[t][in];
        std::array<std::pair<int, int>, 4> pairs{};
        const int n_in = std::popcount(static_cast<unsigned>(in));
        if (n_in == 1 || n_in == 3) {
          const int lone = std::countr_zero(static_cast<unsigned>(n_in == 1 ? in : ~in & 15));
          for (int k = 0; k < 4; ++k) {
            if (k != lone) pairs[poly.count++] = {std::min(k, lone), std::max(k, lone)};
          }
        } else {
          int a = -1, b = -1, c = -1, d = -1;
          for (int k = 0; k < 4; ++k) {
            if (in & (1 << k)) (a < 0 ? a : b) = k;
            else (c < 0 ? c : d) = k;
          }
          for (const auto& [u, v] : {std::pair{a, c}, {a, d}, {b, d}, {b, c}}) {
            pairs[poly.count++] = {std::min(u, v), std::max(u, v)};
          }
        }
        // Orientation: the normal points from the inside corners to the outside ones
        // (the polygon through the edge midpoints turns the same way as through any
        // crossings inside the edges).
        Vec3 mid[4];
        Vec3 dir{0, 0, 0};  // centroid of the outside corners - centroid of the inside ones
        for (int k = 0; k < 4; ++k) {
          const Vec3 p = pos(tet[k]);
          const double w = (in >> k) & 1 ? -1.0 / n_in : 1.0 / (4 - n_in);
          for (int a = 0; a < 3; ++a) dir[a] += w * p[a];
        }
        for (int i = 0; i < poly.count; ++i) {
          const Vec3 p = pos(tet[pairs[i].first]), q = pos(tet[pairs[i].second]);
          for (int a = 0; a < 3; ++a) mid[i][a] = (p[a] + q[a]) / 2;
          poly.edges[i] = edge_index[tet[pairs[i].first]][tet[pairs[i].second]];
        }
        if (dot(newell(mid, poly.count), dir) < 0) {
          std::reverse(poly.edges.begin(), poly.edges.begin() + poly.count);
        }
      }
      for (int opposite = 0; opposite < 4; ++opposite) {
        TetFace& f = faces[t][opposite];
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
        if (f.side < 0) continue;
        Vec3 p[3];
        for (int j = 0; j < 3; ++j) p[j] = pos(f.corners[j]);
        const Vec3 n = cross(sub(p[1], p[0]), sub(p[2], p[0]));
        const double out = f.side % 2 == 0 ? -1.0 : 1.0;
        f.reversed = n[f.side / 2] * out < 0;
      }
    }
    for (int a = 0; a < 3; ++a) {
      const int u = 1 << ((a + 1) % 3), v = 1 << ((a + 2) % 3);
      for (int side = 0; side < 2; ++side) {
        const int o = side == 0 ? 0 : (1 << a);
        auto& quad = side_quads[2 * a + side];
        quad = {o, o | u, o | u | v, o | v};  // normal +axis
        if (side == 0) std::swap(quad[1], quad[3]);
      }
    }
    for (int in = 1; in < 255; ++in) {
      for (int side = 0; side < 6; ++side) {
        int count = 0;
        for (int k : side_quads[side]) count += (in >> k) & 1;
        if (count != 0 && count != 4) crossed_sides[in] |= static_cast<std::uint8_t>(1 << side);
      }
      for (int split = 0; split < 64; ++split) build_loops(in, split);
    }
  }

  // A side's two Kuhn triangles (split along its min-max diagonal), outward order.
  static std::array<std::array<int, 3>, 2> side_triangles(const std::array<int, 4>& q) {
    return {{{q[0], q[1], q[2]}, {q[0], q[2], q[3]}}};
  }

  // The loops of one entry: per side, the region's boundary on the side's two Kuhn
  // triangles (outward order), from each entry crossing to the next exit crossing
  // turned around (the surface runs each shared edge the other way); on an unsplit
  // side the two pieces through the diagonal become one.
  void build_loops(int in, int split) {
    std::array<int, 19> next{};
    next.fill(-1);
    for (int side = 0; side < 6; ++side) {
      const auto& q = side_quads[side];
      const int diagonal = edge_index[q[0]][q[2]];
      int into_diagonal = -1, from_diagonal = -1;
      for (const std::array<int, 3>& tri : side_triangles(q)) {
        int entry = -1, exit = -1;
        for (int i = 0; i < 3; ++i) {
          const int cur = tri[i], nxt = tri[(i + 1) % 3];
          const bool cin = (in >> cur) & 1, nin = (in >> nxt) & 1;
          if (cin == nin) continue;
          (cin ? exit : entry) = edge_index[std::min(cur, nxt)][std::max(cur, nxt)];
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
    CellLoops& out = loops[static_cast<std::size_t>(in) * 64 + static_cast<std::size_t>(split)];
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
        const bool on_diagonal = std::popcount(static_cast<unsigned>(edges[e].p ^ edges[e].q)) == 2;
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
};

const Tables& tables() {
  static const Tables t;
  return t;
}

// A lattice point's cell (clamped to the node) and its fractions there, for trilinear
// interpolation.
struct CellPoint {
  std::size_t index = 0;  // sample of the cell's corner 0
  double f[3]{};
  std::array<std::uint32_t, 3> cell{};
};

struct Trilinear {
  double value;
  Vec3 gradient;  // lattice units
};

template <class Sample>
Trilinear trilinear(const Sample* field, const std::array<std::size_t, 3>& dims, const CellPoint& cp,
                    bool with_gradient) {
  const std::size_t sy = dims[0], sz = dims[0] * dims[1];
  const Sample* b = field + cp.index;
  const double c0 = b[0], c1 = b[1], c2 = b[sy], c3 = b[sy + 1];
  const double c4 = b[sz], c5 = b[sz + 1], c6 = b[sz + sy], c7 = b[sz + sy + 1];
  const double fx = cp.f[0], fy = cp.f[1], fz = cp.f[2];
  // (1 - f) a + f b is a at f = 0 and b at f = 1 exactly (a + f (b - a) need not be b):
  // a vertex on a node face gets the same value from the cell on either side, so the
  // nodes sharing it carry the same attribute bits (and a height placed by one).
  auto lerp = [](double a, double b, double f) { return (1.0 - f) * a + f * b; };
  const double x00 = lerp(c0, c1, fx), x10 = lerp(c2, c3, fx);
  const double x01 = lerp(c4, c5, fx), x11 = lerp(c6, c7, fx);
  const double y0 = lerp(x00, x10, fy), y1 = lerp(x01, x11, fy);
  Trilinear t;
  t.value = lerp(y0, y1, fz);
  if (with_gradient) {
    const double dx00 = c1 - c0, dx10 = c3 - c2, dx01 = c5 - c4, dx11 = c7 - c6;
    const double dx0 = dx00 + fy * (dx10 - dx00), dx1 = dx01 + fy * (dx11 - dx01);
    t.gradient[0] = dx0 + fz * (dx1 - dx0);
    t.gradient[1] = (x10 - x00) + fz * ((x11 - x01) - (x10 - x00));
    t.gradient[2] = y1 - y0;
  } else {
    t.gradient = {0, 0, 0};
  }
  return t;
}

// A vertex remembered per lattice element (a corner or a lattice edge): tag = stamp
// << 8 | group, valid while the stamp is current.
struct Slot {
  std::uint32_t tag = 0;
  std::uint32_t vertex = 0;
};
constexpr std::uint32_t kStampLimit = 1u << 24;

// Per-thread buffers, kept across extractions so that a node costs no fresh pages.
struct Scratch {
  ConditionSet set;
  MeshBuilder builder;
  TetClipper clipper;
  std::vector<Vec3> pts;
  // Condition vertices: per sample 8 slots (0 the sample itself, 1..7 the lattice edge
  // towards the corner with those bits set), for two slabs of samples (z even, z odd):
  // cells of slab z only reach samples of slabs z and z + 1. Slab z's stamp is
  // stamp + z, so slots of slab z - 1 left in its place are stale.
  std::vector<Slot> lattice;
  // Node-side vertices: per side, per sample of the side's plane, 4 slots (0 the
  // sample, 1 the edge along the plane's first axis, 2 along its second, 3 the
  // diagonal); stamp + dims[2].
  std::array<std::vector<Slot>, 6> sides;
  // Node-side squares of wholly inside cells, per side (1 = inside; first plane axis
  // fastest), made into rectangles once every cell is done; cleared by begin().
  std::array<std::vector<std::uint8_t>, 6> inside_squares;
  std::uint32_t stamp = 0;       // this extraction's first stamp
  std::uint32_t next_stamp = 1;  // the next extraction's
  std::vector<std::uint64_t> row_or, row_and;
  // Per column of samples of the current row of cells: the conditions that hold at one
  // of its four samples and at all four, in the masks' width.
  std::vector<std::uint16_t> col_or16, col_and16;
  std::vector<std::uint64_t> col_or64, col_and64;
  std::vector<std::uint8_t> needs_fallback;
  std::vector<std::uint8_t> multi;  // per cell: crossed by several conditions
  std::vector<Vec3> fallback;
  std::vector<CellPoint> cells;
  std::array<std::vector<double>, 3> inverse_spacing;

  template <class Mask>
  std::pair<std::vector<Mask>&, std::vector<Mask>&> columns() {
    if constexpr (sizeof(Mask) == sizeof(std::uint16_t)) {
      return {col_or16, col_and16};
    } else {
      return {col_or64, col_and64};
    }
  }

  void begin(std::size_t samples, const std::array<std::size_t, 3>& dims) {
    const std::size_t slab = samples / dims[2];
    if (lattice.size() < 2 * slab * 8) lattice.resize(2 * slab * 8);
    for (int a = 0; a < 3; ++a) {
      const std::size_t plane = dims[(a + 1) % 3] * dims[(a + 2) % 3] * 4;
      const std::size_t squares = (dims[(a + 1) % 3] - 1) * (dims[(a + 2) % 3] - 1);
      for (int s = 0; s < 2; ++s) {
        if (sides[2 * a + s].size() < plane) sides[2 * a + s].resize(plane);
        auto& sq = inside_squares[2 * a + s];
        if (sq.size() < squares) sq.resize(squares);
        std::fill(sq.begin(), sq.begin() + static_cast<std::ptrdiff_t>(squares), 0);
      }
    }
    // Stamps stamp .. stamp + dims[2], all above those of earlier extractions.
    const auto used = static_cast<std::uint32_t>(dims[2] + 1);
    stamp = next_stamp;
    if (stamp == 0 || used >= kStampLimit - stamp) {  // wrapped: forget every slot
      std::fill(lattice.begin(), lattice.end(), Slot{});
      for (auto& s : sides) std::fill(s.begin(), s.end(), Slot{});
      stamp = 1;
    }
    next_stamp = stamp + used;
    builder.reset();
  }
};

// The cell loop's vertex and polygon work for one extraction: vertices on lattice
// corners and edges are found by element (slots), the rest by position.
class Kernel {
 public:
  Kernel(Scratch& s, const ConditionSet& set, const std::array<std::size_t, 3>& dims,
         std::uint32_t side_group)
      : s_(s),
        set_(set),
        b_(s.builder),
        dims_(dims),
        side_group_(side_group),
        side_stamp_((s.stamp + static_cast<std::uint32_t>(dims[2])) << 8) {
    const std::size_t sx = 1, sy = dims[0], sz = dims[0] * dims[1];
    offsets_ = {0, sx, sy, sx + sy, sz, sz + sx, sz + sy, sz + sx + sy};
  }

  void set_cell(std::size_t x, std::size_t y, std::size_t z, int boundary) {
    x_ = x;
    y_ = y;
    z_ = z;
    base_ = (z * dims_[1] + y) * dims_[0] + x;
    boundary_ = boundary;
    cell_valid_ = 0;
    const std::size_t slab = dims_[0] * dims_[1];
    for (int k = 0; k < 8; ++k) {
      const std::size_t zk = z + ((k >> 2) & 1);
      slot_[k] = ((zk & 1) * slab + (y + ((k >> 1) & 1)) * dims_[0] + x + (k & 1)) * 8;
    }
    slab_stamp_[0] = (s_.stamp + static_cast<std::uint32_t>(z)) << 8;
    slab_stamp_[1] = (s_.stamp + static_cast<std::uint32_t>(z + 1)) << 8;
  }

  // A cell wholly inside: only its faces on the node boundary are made, from node-side
  // vertices, so the lattice slots of set_cell are not needed.
  void set_inside_cell(std::size_t x, std::size_t y, std::size_t z, int boundary) {
    x_ = x;
    y_ = y;
    z_ = z;
    boundary_ = boundary;
  }

  Vec3 corner_pos(int k) const {
    return Vec3{static_cast<double>(x_ + (k & 1)), static_cast<double>(y_ + ((k >> 1) & 1)),
                static_cast<double>(z_ + ((k >> 2) & 1))};
  }
  std::size_t sample(int k) const { return base_ + offsets_[k]; }

  // Vertex of condition c at cell corner k.
  std::uint32_t condition_corner(std::uint32_t c, int k) {
    return lookup(s_.lattice[slot_[k]], slab_stamp_[k >> 2], c, k);
  }

  // Vertex of condition c on cell edge e (its values change sign along it).
  std::uint32_t condition_edge(std::uint32_t c, int e) {
    const CellEdge& ce = tables().edges[e];
    const std::size_t sp = sample(ce.p);
    Slot& slot = s_.lattice[slot_[ce.p] + static_cast<std::size_t>(ce.p ^ ce.q)];
    const std::uint32_t stamp = slab_stamp_[ce.p >> 2];
    if (slot.tag == (stamp | c)) return slot.vertex;
    const Condition& cond = set_.conditions[c];
    const Vec3 P = corner_pos(ce.p), Q = corner_pos(ce.q);
    const EdgeCrossing x = edge_crossing(P, Q, cond.value(sp), cond.value(sample(ce.q)));
    std::uint32_t v;
    if (x.t == 0.0) {
      v = condition_corner(c, ce.p);
    } else if (x.t == 1.0) {
      v = condition_corner(c, ce.q);
    } else if ((slot.tag & ~0xFFu) == stamp) {
      return b_.vertex(c, x.p);  // the slot holds another condition's vertex
    } else {
      v = b_.add_vertex(c, x.p);
    }
    if ((slot.tag & ~0xFFu) != stamp) slot = Slot{stamp | c, v};
    return v;
  }

  // Cached per cell (one condition crosses the whole cell).
  std::uint32_t cell_edge(std::uint32_t c, int e) {
    if (cell_valid_ & (1u << e)) return cell_vertex_[e];
    cell_valid_ |= 1u << e;
    return cell_vertex_[e] = condition_edge(c, e);
  }

  // Vertex of node side `side` at cell corner k.
  std::uint32_t side_corner(int side, int k) {
    return lookup(side_slot(side, k, 0), side_stamp_, side_group_ + static_cast<std::uint32_t>(side), k);
  }

  // Vertex of node side `side` where condition c crosses the cell edge p-q (in the side).
  std::uint32_t side_edge(int side, std::uint32_t c, int p, int q) {
    const int a = side / 2;
    const int u = 1 << ((a + 1) % 3), v = 1 << ((a + 2) % 3);
    const int d = p ^ q;
    const int kind = (d & u ? 1 : 0) + (d & v ? 2 : 0);
    Slot& slot = side_slot(side, p, kind);
    const std::uint32_t group = side_group_ + static_cast<std::uint32_t>(side);
    const std::uint32_t stamp = side_stamp_;
    if (slot.tag == (stamp | group)) return slot.vertex;
    const Condition& cond = set_.conditions[c];
    const Vec3 P = corner_pos(p), Q = corner_pos(q);
    const EdgeCrossing x = edge_crossing(P, Q, cond.value(sample(p)), cond.value(sample(q)));
    std::uint32_t vtx;
    if (x.t == 0.0) {
      vtx = side_corner(side, p);
    } else if (x.t == 1.0) {
      vtx = side_corner(side, q);
    } else if ((slot.tag & ~0xFFu) == stamp) {
      return b_.vertex(group, x.p);
    } else {
      vtx = b_.add_vertex(group, x.p);
    }
    if ((slot.tag & ~0xFFu) != stamp) slot = Slot{stamp | group, vtx};
    return vtx;
  }

  // A wholly inside cell: its faces on the node boundary, kept as squares of the side
  // for inside_rectangles().
  void inside_cell_faces() {
    for (int side = 0; side < 6; ++side) {
      if (boundary_ & (1 << side)) mark_inside_square(side);
    }
  }

  // The face of the current cell on node side `side` is wholly inside.
  void mark_inside_square(int side) {
    const int a = side / 2;
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    const std::size_t cell[3]{x_, y_, z_};
    s_.inside_squares[side][cell[v] * (dims_[u] - 1) + cell[u]] = 1;
  }

  // The marked squares of every node side, as few rectangles as a greedy sweep finds,
  // each triangulated through every lattice point on its perimeter and none inside it:
  // the triangles along a rectangle's edges are unit lattice segments, as the faces of
  // the cut cells and rectangles beside it (and the node sides meeting it at the node's
  // edges) have, so the mesh stays closed; a w x h rectangle takes 2 (w + h) - 2
  // triangles instead of 2 w h. Clears the marks.
  // `merge` false: every square on its own (two triangles), for output frames that bend
  // straight lines of the lattice (a big rectangle's chords would cut through a thin
  // layer on a curved Earth).
  void inside_rectangles(bool merge) {
    for (int side = 0; side < 6; ++side) {
      const int a = side / 2;
      const std::size_t nu = dims_[(a + 1) % 3] - 1, nv = dims_[(a + 2) % 3] - 1;
      std::uint8_t* sq = s_.inside_squares[side].data();
      for (std::size_t v0 = 0; v0 < nv; ++v0) {
        for (std::size_t u0 = 0; u0 < nu; ++u0) {
          if (!sq[v0 * nu + u0]) continue;
          std::size_t w = 1;
          while (merge && u0 + w < nu && sq[v0 * nu + u0 + w]) ++w;
          std::size_t h = 1;
          for (bool full = merge; full && v0 + h < nv; h += full ? 1 : 0) {
            const std::uint8_t* row = sq + (v0 + h) * nu + u0;
            full = std::all_of(row, row + w, [](std::uint8_t b) { return b != 0; });
          }
          for (std::size_t dv = 0; dv < h; ++dv) std::fill_n(sq + (v0 + dv) * nu + u0, w, 0);
          rectangle(side, u0, v0, w, h);
        }
      }
    }
  }

  // Rectangle [u0, u0 + w] x [v0, v0 + h] of lattice points on node side `side` (u, v
  // its first and second plane axes, as in side_slot()): the strip between its left and
  // right edges, with the strip's first triangle fanned from its upper right corner
  // through the bottom edge's points and its last fanned from its lower left corner
  // through the top edge's points. Counter-clockwise in (u, v) is outward on an upper
  // side.
  void rectangle(int side, std::size_t u0, std::size_t v0, std::size_t w, std::size_t h) {
    const int a = side / 2;
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    const std::uint32_t group = side_group_ + static_cast<std::uint32_t>(side);
    const bool upper = side % 2 == 1;
    // The side's vertex at lattice point (pu, pv): the slot side_slot() gives a cell
    // corner there (pv * dims[u] + pu in every side's plane).
    auto point = [&](std::size_t pu, std::size_t pv) {
      Slot& slot = s_.sides[side][(pv * dims_[u] + pu) * 4];
      return lookup(slot, side_stamp_, group, [&] {
        Vec3 p;
        p[a] = upper ? static_cast<double>(dims_[a] - 1) : 0.0;
        p[u] = static_cast<double>(pu);
        p[v] = static_cast<double>(pv);
        return p;
      });
    };
    auto triangle = [&](std::uint32_t p, std::uint32_t q, std::uint32_t r) {
      if (upper) {
        b_.triangle(group, p, q, r);
      } else {
        b_.triangle(group, p, r, q);
      }
    };
    const std::size_t u1 = u0 + w, v1 = v0 + h;
    // Bottom edge, fanned from (u1, v0 + 1).
    const std::uint32_t bottom_apex = point(u1, v0 + 1);
    std::uint32_t prev = point(u0, v0);
    for (std::size_t i = u0 + 1; i <= u1; ++i) {
      const std::uint32_t next = point(i, v0);
      triangle(prev, next, bottom_apex);
      prev = next;
    }
    // The strip between the left and right edges; its row at the top is fanned.
    for (std::size_t j = v0; j < v1; ++j) {
      const std::uint32_t left = point(u0, j), left_up = point(u0, j + 1);
      const std::uint32_t right_up = point(u1, j + 1);
      if (j > v0) triangle(left, point(u1, j), right_up);
      if (j + 1 < v1) {
        triangle(left, right_up, left_up);
      } else {
        // Top edge, fanned from (u0, v1 - 1).
        std::uint32_t top = left_up;
        for (std::size_t i = u0 + 1; i <= u1; ++i) {
          const std::uint32_t next = point(i, v1);
          triangle(left, next, top);
          top = next;
        }
      }
    }
  }

  // One tetrahedron whose only crossing condition is c (bits: c's inside bits of its
  // corners, 1..14): the polygon on c's plane and its faces on the node boundary.
  void simple_tet(int t, std::uint32_t c, int bits) {
    const Tables& tb = tables();
    const TetPolygon& poly = tb.polygons[t][bits];
    auto id = [&](int i) { return condition_edge(c, poly.edges[i]); };
    const std::uint32_t a = id(0), b = id(1), d = id(2);
    if (poly.count == 3) {
      b_.oriented_triangle(c, a, b, d);
    } else {
      b_.oriented_quad(c, a, b, d, id(3));
    }
    if (boundary_ == 0) return;
    for (int opposite = 0; opposite < 4; ++opposite) {
      const TetFace& f = tb.faces[t][opposite];
      if (f.side < 0 || !(boundary_ & (1 << f.side))) continue;
      const std::array<bool, 3> in{((bits >> f.local[0]) & 1) != 0, ((bits >> f.local[1]) & 1) != 0,
                                   ((bits >> f.local[2]) & 1) != 0};
      side_triangle_part(f.side, c, f.corners, in, f.reversed);
    }
  }

  // The inside part of one triangle on node side `side` (cube corners `corners`, their
  // inside flags for condition c `in`), clipped Sutherland-Hodgman by c, in the
  // triangle's order or reversed, and emitted on that side's group.
  void side_triangle_part(int side, std::uint32_t c, const std::array<int, 3>& corners,
                          const std::array<bool, 3>& in, bool reversed) {
    std::uint32_t ids[4];
    std::size_t m = 0;
    for (int i = 0; i < 3; ++i) {
      const int cur = corners[i], nxt = corners[(i + 1) % 3];
      if (in[i]) ids[m++] = side_corner(side, cur);
      if (in[i] != in[(i + 1) % 3]) ids[m++] = side_edge(side, c, std::min(cur, nxt), std::max(cur, nxt));
    }
    if (reversed) std::reverse(ids, ids + m);
    const std::uint32_t group = side_group_ + static_cast<std::uint32_t>(side);
    if (m == 3) {
      b_.oriented_triangle(group, ids[0], ids[1], ids[2]);
    } else if (m == 4) {
      b_.oriented_quad(group, ids[0], ids[1], ids[2], ids[3]);
    }
  }

  // A cell whose only crossing condition is c: its loops on c's surface (table entry),
  // cell edge vertices cached per cell.
  void cell_loops(std::uint32_t c, const CellLoops& cl) {
    std::uint32_t ids[18];
    int k = 0;
    for (int l = 0; l < cl.loops; ++l) {
      const int n = cl.size[l];
      for (int i = 0; i < n; ++i) ids[i] = cell_edge(c, cl.edges[k + i]);
      k += n;
      if (n == 3) {
        b_.oriented_triangle(c, ids[0], ids[1], ids[2]);
      } else if (n == 4) {
        b_.oriented_quad(c, ids[0], ids[1], ids[2], ids[3]);
      } else {
        b_.oriented_polygon(c, ids, static_cast<std::size_t>(n));
      }
    }
  }

  // The same cell's faces on the node boundary: per side, the inside part of each of
  // its two Kuhn triangles (Sutherland-Hodgman by c), so that the node beyond, whatever
  // crosses its cells there, meets the same crossings.
  void side_caps(std::uint32_t c, int bits) {
    const Tables& tb = tables();
    for (int side = 0; side < 6; ++side) {
      if (!(boundary_ & (1 << side))) continue;
      const auto& quad = tb.side_quads[side];
      const int face_bits = (1 << quad[0]) | (1 << quad[1]) | (1 << quad[2]) | (1 << quad[3]);
      if ((bits & face_bits) == face_bits) {  // the whole face
        mark_inside_square(side);
        continue;
      }
      for (const std::array<int, 3>& tri : Tables::side_triangles(quad)) {
        const std::array<bool, 3> in{((bits >> tri[0]) & 1) != 0, ((bits >> tri[1]) & 1) != 0,
                                     ((bits >> tri[2]) & 1) != 0};
        side_triangle_part(side, c, tri, in, false);
      }
    }
  }

  // A tetrahedron wholly inside: its faces on the node boundary.
  void inside_tet(int t) {
    const Tables& tb = tables();
    for (int opposite = 0; opposite < 4; ++opposite) {
      const TetFace& f = tb.faces[t][opposite];
      if (f.side < 0 || !(boundary_ & (1 << f.side))) continue;
      const std::uint32_t a = side_corner(f.side, f.corners[0]);
      const std::uint32_t b = side_corner(f.side, f.corners[1]);
      const std::uint32_t c = side_corner(f.side, f.corners[2]);
      const std::uint32_t group = side_group_ + static_cast<std::uint32_t>(f.side);
      if (f.reversed) {
        b_.triangle(group, a, c, b);
      } else {
        b_.triangle(group, a, b, c);
      }
    }
  }

  // A tetrahedron crossed by several conditions: the general clipper, vertices welded
  // by position.
  void clipped_tet(int t, std::uint64_t conditions) {
    const Tables& tb = tables();
    const auto& tet = kTets[t];
    const std::array<std::size_t, 4> ids{sample(tet[0]), sample(tet[1]), sample(tet[2]),
                                         sample(tet[3])};
    const std::array<Vec3, 4> pos{corner_pos(tet[0]), corner_pos(tet[1]), corner_pos(tet[2]),
                                  corner_pos(tet[3])};
    TetClipper& clipper = s_.clipper;
    if (!clipper.clip(ids, pos, set_, conditions)) return;
    const auto& loop = clipper.loop();
    for (const auto& face : clipper.faces()) {
      Vec3 outward;
      std::uint32_t group;
      if (face.tag < 4) {
        const int side = tb.faces[t][face.tag].side;
        if (side < 0 || !(boundary_ & (1 << side))) continue;
        outward = {0, 0, 0};
        outward[side / 2] = side % 2 == 0 ? -1.0 : 1.0;
        group = side_group_ + static_cast<std::uint32_t>(side);
      } else {
        const std::size_t c = static_cast<std::size_t>(face.tag - 4);
        const Vec3 g = clipper.gradient(c);
        outward = {-g[0], -g[1], -g[2]};
        group = static_cast<std::uint32_t>(c);
      }
      s_.pts.clear();
      for (std::uint32_t i = 0; i < face.count; ++i) {
        s_.pts.push_back(clipper.position(loop[face.first + i]));
      }
      b_.polygon(group, s_.pts.data(), s_.pts.size(), outward);
    }
  }

 private:
  Slot& side_slot(int side, int k, int kind) {
    const std::size_t cx = x_ + (k & 1), cy = y_ + ((k >> 1) & 1), cz = z_ + ((k >> 2) & 1);
    // In the side's plane: first axis (axis + 1) % 3, second (axis + 2) % 3.
    const std::size_t index = side < 2 ? cz * dims_[1] + cy : side < 4 ? cx * dims_[2] + cz : cy * dims_[0] + cx;
    return s_.sides[side][index * 4 + static_cast<std::size_t>(kind)];
  }

  // The vertex of `group` at cell corner k, remembered in `slot`.
  std::uint32_t lookup(Slot& slot, std::uint32_t stamp, std::uint32_t group, int k) {
    return lookup(slot, stamp, group, [&] { return corner_pos(k); });
  }

  // The same at the lattice point position() gives (called only when the slot does not
  // hold the vertex).
  template <class Position>
  std::uint32_t lookup(Slot& slot, std::uint32_t stamp, std::uint32_t group, Position position) {
    if (slot.tag == (stamp | group)) return slot.vertex;
    if ((slot.tag & ~0xFFu) == stamp) return b_.vertex(group, position());  // another group's
    const std::uint32_t v = b_.add_vertex(group, position());
    slot = Slot{stamp | group, v};
    return v;
  }

  Scratch& s_;
  const ConditionSet& set_;
  MeshBuilder& b_;
  std::array<std::size_t, 3> dims_;
  std::array<std::size_t, 8> offsets_{};
  std::uint32_t side_group_;
  std::uint32_t side_stamp_;  // tag (without group) of the side slots: stamp + dims[2]
  std::size_t x_ = 0, y_ = 0, z_ = 0, base_ = 0;
  int boundary_ = 0;
  std::uint32_t cell_valid_ = 0;
  std::array<std::uint32_t, 19> cell_vertex_{};
  std::array<std::size_t, 8> slot_{};  // lattice slot of each corner
  std::array<std::uint32_t, 2> slab_stamp_{};  // tags (without group) of slabs z, z + 1
};

// Every cell of the node through the kernel, over masks of one width: rows of cells
// skipped or taken whole by their sample rows' summaries, cells crossed by several
// conditions found first, then each cut cell by table or per tetrahedron.
template <class Mask>
void extract_cells(const Mask* inside, const ConditionSet& set,
                   const std::array<std::size_t, 3>& dims, Scratch& scratch, Kernel& kernel,
                   ExtractStats& local) {
  const std::size_t sy = dims[0], sz = dims[0] * dims[1];
  const std::uint64_t all = set.all;
  const auto& cell_loops = tables().loops;

  // Per row of samples (y, z): the conditions that hold somewhere and everywhere on it.
  const std::size_t rows = dims[1] * dims[2];
  scratch.row_or.resize(rows);
  scratch.row_and.resize(rows);
  for (std::size_t r = 0; r < rows; ++r) {
    const Mask* row = inside + r * dims[0];
    Mask o = 0, a = static_cast<Mask>(all);  // narrow masks: all fits
    for (std::size_t x = 0; x < dims[0]; ++x) {
      o |= row[x];
      a &= row[x];
    }
    scratch.row_or[r] = o;
    scratch.row_and[r] = a;
  }
  auto [col_or_buffer, col_and_buffer] = scratch.columns<Mask>();
  col_or_buffer.resize(dims[0]);
  col_and_buffer.resize(dims[0]);
  Mask* col_or = col_or_buffer.data();
  Mask* col_and = col_and_buffer.data();
  auto fill_columns = [&](std::size_t r0) {
    const Mask* s0 = inside + r0 * dims[0];
    const Mask* s1 = s0 + sy;
    const Mask* s2 = s0 + sz;
    const Mask* s3 = s0 + sz + sy;
    for (std::size_t x = 0; x < dims[0]; ++x) {
      col_or[x] = s0[x] | s1[x] | s2[x] | s3[x];
      col_and[x] = s0[x] & s1[x] & s2[x] & s3[x];
    }
  };
  // A row of cells (y, z) as its four sample rows summarise it: every condition holds
  // somewhere (else the row is skipped) and the conditions that hold everywhere.
  auto row_summary = [&](std::size_t r0, std::uint64_t& row_or, std::uint64_t& row_and) {
    const std::size_t rr[4]{r0, r0 + 1, r0 + dims[1], r0 + dims[1] + 1};
    row_or = 0;
    row_and = all;
    for (std::size_t r : rr) {
      row_or |= scratch.row_or[r];
      row_and &= scratch.row_and[r];
    }
  };

  // Cells crossed by several conditions (cut into tetrahedra): the cells crossed by one
  // condition beside them split the shared side along its diagonal, as the tetrahedra
  // do. Looked for only where two conditions can cross one row of cells.
  const std::size_t cx = dims[0] - 1, cy = dims[1] - 1;
  bool any_multi = false;
  std::uint64_t holds_everywhere = all;
  for (std::size_t r = 0; r < rows; ++r) holds_everywhere &= scratch.row_and[r];
  if (std::popcount(all & ~holds_everywhere) >= 2) {
    scratch.multi.assign(cx * cy * (dims[2] - 1), 0);
    for (std::size_t z = 0; z + 1 < dims[2]; ++z) {
      for (std::size_t y = 0; y + 1 < dims[1]; ++y) {
        const std::size_t r0 = z * dims[1] + y;
        std::uint64_t row_or, row_and;
        row_summary(r0, row_or, row_and);
        if ((row_or & all) != all || std::popcount(all & ~row_and) < 2) continue;
        fill_columns(r0);
        for (std::size_t x = 0; x + 1 < dims[0]; ++x) {
          if (((col_or[x] | col_or[x + 1]) & all) != all) continue;
          const std::uint64_t mixed = all & ~(col_and[x] & col_and[x + 1]);
          if ((mixed & (mixed - 1)) == 0) continue;
          scratch.multi[(z * cy + y) * cx + x] = 1;
          any_multi = true;
        }
      }
    }
  }
  const std::uint8_t* multi = scratch.multi.data();

  for (std::size_t z = 0; z + 1 < dims[2]; ++z) {
    for (std::size_t y = 0; y + 1 < dims[1]; ++y) {
      // A row of cells: skip it whole when a condition fails on all four sample rows;
      // when every condition holds on all of them only its cells on the node boundary
      // have faces.
      const std::size_t r0 = z * dims[1] + y;
      std::uint64_t row_or, row_and;
      row_summary(r0, row_or, row_and);
      if ((row_or & all) != all) continue;
      const int yz_boundary = (y == 0 ? 1 << 2 : 0) | (y + 2 == dims[1] ? 1 << 3 : 0) |
                              (z == 0 ? 1 << 4 : 0) | (z + 2 == dims[2] ? 1 << 5 : 0);
      if (row_and == all) {
        local.inside_cells += dims[0] - 1;
        for (std::size_t x = 0; x + 1 < dims[0]; ++x) {
          const int boundary = yz_boundary | (x == 0 ? 1 : 0) | (x + 2 == dims[0] ? 2 : 0);
          if (boundary == 0) continue;
          kernel.set_inside_cell(x, y, z, boundary);
          kernel.inside_cell_faces();
        }
        continue;
      }
      const Mask* s0 = inside + r0 * dims[0];
      const Mask* s1 = s0 + sy;
      const Mask* s2 = s0 + sz;
      const Mask* s3 = s0 + sz + sy;
      fill_columns(r0);
      for (std::size_t x = 0; x + 1 < dims[0]; ++x) {
        if (((col_or[x] | col_or[x + 1]) & all) != all) continue;  // a condition fails at every corner
        const std::uint64_t cell_and = col_and[x] & col_and[x + 1] & all;
        const int boundary = yz_boundary | (x == 0 ? 1 : 0) | (x + 2 == dims[0] ? 2 : 0);
        if (cell_and == all) {
          ++local.inside_cells;
          if (boundary != 0) {
            kernel.set_inside_cell(x, y, z, boundary);
            kernel.inside_cell_faces();
          }
          continue;
        }
        ++local.cut_cells;
        kernel.set_cell(x, y, z, boundary);
        std::uint64_t masks[8];
        masks[0] = s0[x];
        masks[1] = s0[x + 1];
        masks[2] = s1[x];
        masks[3] = s1[x + 1];
        masks[4] = s2[x];
        masks[5] = s2[x + 1];
        masks[6] = s3[x];
        masks[7] = s3[x + 1];
        const std::uint64_t mixed = all & ~cell_and;
        if ((mixed & (mixed - 1)) == 0) {
          // One condition crosses the cell: its loops by table, split along the
          // diagonal on the node's boundary and next to cells cut into tetrahedra.
          const int c = std::countr_zero(mixed);
          int cell_bits = 0;
          for (int k = 0; k < 8; ++k) cell_bits |= static_cast<int>((masks[k] >> c) & 1) << k;
          int split = boundary;
          if (any_multi) {
            const std::size_t cell = (z * cy + y) * cx + x;
            const std::size_t cz = cx * cy;
            split |= (x > 0 && multi[cell - 1] ? 1 : 0) | (x + 2 < dims[0] && multi[cell + 1] ? 2 : 0) |
                     (y > 0 && multi[cell - cx] ? 4 : 0) | (y + 2 < dims[1] && multi[cell + cx] ? 8 : 0) |
                     (z > 0 && multi[cell - cz] ? 16 : 0) | (z + 2 < dims[2] && multi[cell + cz] ? 32 : 0);
          }
          split &= tables().crossed_sides[static_cast<std::size_t>(cell_bits)];
          ++local.table_cells;
          const std::size_t entry = static_cast<std::size_t>(cell_bits) * 64 + static_cast<std::size_t>(split);
          kernel.cell_loops(static_cast<std::uint32_t>(c), cell_loops[entry]);
          if (boundary != 0) kernel.side_caps(static_cast<std::uint32_t>(c), cell_bits);
          continue;
        }
        // Several conditions cross the cell: per tetrahedron.
        for (int t = 0; t < 6; ++t) {
          const auto& tet = kTets[t];
          std::uint64_t t_and = all, t_or = 0;
          for (int k : tet) {
            t_and &= masks[k];
            t_or |= masks[k];
          }
          if ((t_or & all) != all) continue;
          if (t_and == all) {
            if (boundary != 0) kernel.inside_tet(t);
            continue;
          }
          const std::uint64_t tet_mixed = all & ~t_and;
          if ((tet_mixed & (tet_mixed - 1)) == 0) {
            ++local.simple_tets;
            const int c = std::countr_zero(tet_mixed);
            int bits = 0;
            for (int k = 0; k < 4; ++k) bits |= static_cast<int>((masks[tet[k]] >> c) & 1) << k;
            kernel.simple_tet(t, static_cast<std::uint32_t>(c), bits);
            continue;
          }
          ++local.clipped_tets;
          kernel.clipped_tet(t, tet_mixed);
        }
      }
    }
  }
}

}  // namespace

Mesh extract_node_mesh(const NodeSamples& samples, const ExtractRequest& request,
                       ExtractStats* stats) {
  const auto dims = samples.dims();
  const std::uint64_t corner_crossings_before = corner_crossings;
  thread_local Scratch scratch;
  ConditionSet& set = scratch.set;
  build_conditions(samples, request, set);
  if (request.attribute_fields.size() != request.attribute_names.size()) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "sub-volume {}: {} attribute fields but {} names", request.subvolume_id,
                     request.attribute_fields.size(), request.attribute_names.size());
  }
  for (std::uint32_t f : request.attribute_fields) {
    if (f >= samples.fields.size() || samples.fields[f].size() != samples.sample_count()) {
      throw make_error(ErrorCode::kInvalidArgument, "sub-volume {}: attribute field {} missing",
                       request.subvolume_id, f);
    }
  }
  Mesh mesh;
  mesh.subvolume_id = request.subvolume_id;
  mesh.attribute_names = request.attribute_names;
  mesh.attributes.resize(request.attribute_fields.size());
  ExtractStats local;
  local.cells = (dims[0] - 1) * (dims[1] - 1) * (dims[2] - 1);
  local.conditions = set.conditions.size();
  local.empty_by_condition = set.empty;
  if (set.empty) {
    if (stats) *stats = local;
    return mesh;
  }

  const std::size_t c_count = set.conditions.size();
  const std::uint32_t side_group = static_cast<std::uint32_t>(c_count);  // + 2 * axis + side
  scratch.begin(samples.sample_count(), dims);
  MeshBuilder& builder = scratch.builder;
  Kernel kernel(scratch, set, dims, side_group);

  if (set.narrow) {
    extract_cells(set.inside16.data(), set, dims, scratch, kernel, local);
  } else {
    extract_cells(set.inside64.data(), set, dims, scratch, kernel, local);
  }
  kernel.inside_rectangles(request.merge_face_squares);

  // Lattice to axis coordinates, normals, attributes: once per vertex.
  builder.drop_unused_vertices();
  int descending = 0;
  for (int a = 0; a < 3; ++a) descending += samples.coords[a].back() < samples.coords[a].front();
  const std::size_t nv = builder.points.size();
  const std::size_t nt = builder.triangle_count();
  mesh.face_kinds.reserve(nt);

  // Per group: face kind and normal rule.
  const std::size_t groups = c_count + 6;
  std::array<FaceKind, kMaxConditions + 6> kind_of{};
  for (std::size_t g = 0; g < groups; ++g) {
    if (g >= side_group) {
      const std::size_t side = g - side_group;
      kind_of[g] = samples.grid_edge[side]          ? FaceKind::kGridBoundary
                   : (set.box_sides >> side) & 1u ? FaceKind::kDomainBox
                                                  : FaceKind::kNodeBoundary;
    } else {
      const ConditionKind k = set.conditions[g].kind;
      kind_of[g] = k == ConditionKind::kBox || k == ConditionKind::kSample ? FaceKind::kDomainBox
                                                                           : FaceKind::kLimit;
    }
  }
  // The lattice-space orientation is the axis-space one unless an odd number of axes
  // descend.
  const auto* triangles = builder.triangles();
  if (descending % 2 == 1) {
    mesh.triangles.reserve(nt);
    for (std::size_t t = 0; t < nt; ++t) {
      mesh.triangles.push_back({triangles[t][0], triangles[t][2], triangles[t][1]});
    }
  } else {
    mesh.triangles.assign(triangles, triangles + nt);
  }
  const std::uint32_t* triangle_groups = builder.triangle_groups();
  for (std::size_t t = 0; t < nt; ++t) mesh.face_kinds.push_back(kind_of[triangle_groups[t]]);

  std::vector<const float*> attribute_data;
  for (std::uint32_t f : request.attribute_fields) attribute_data.push_back(samples.fields[f].data());
  scratch.needs_fallback.assign(nv, 0);
  bool any_fallback = false;
  // Per axis and cell: the spacing's inverse (normals are covectors: the lattice
  // gradient divided by the spacing).
  //
  // And whether a point strictly inside a cell may round onto one of the cell's ends
  // in axis coordinates (c0 + f (c1 - c0) equal to c0 or c1 for 0 < f < 1), which the
  // mapping below then checks vertex by vertex. Every vertex but the general clipper's
  // is a lattice point or a crossing on a lattice edge, whose fraction of its cell along
  // each axis is 0, 1, or at least kCrossingSnap (2^-30) away from both (edge_crossing
  // snaps nearer crossings to the corner; computing f = p - i costs far less than
  // 2^-31 on any lattice under 2^20 samples a side). Rounding onto an end then needs a
  // spacing below 2^-21 of the coordinates' magnitude (|f (c1 - c0)| must be under
  // half an ulp of c0); an axis whose every spacing is at least 2^-18 of it is safe
  // with room to spare (degrees, metres and pascals on any model grid are, by many
  // orders of magnitude).
  static_assert(kCrossingSnap >= 0x1p-30);
  bool may_round = local.clipped_tets > 0;
  for (int a = 0; a < 3; ++a) {
    auto& inv = scratch.inverse_spacing[a];
    const auto& c = samples.coords[a];
    inv.resize(dims[a] - 1);
    for (std::size_t i = 0; i + 1 < dims[a]; ++i) {
      const double spacing = c[i + 1] - c[i];
      inv[i] = 1.0 / spacing;
      const double magnitude = std::max(std::fabs(c[i]), std::fabs(c[i + 1]));
      may_round = may_round || !(std::fabs(spacing) >= 0x1p-18 * magnitude);
    }
  }
  // Per group: the limit field whose gradient gives the normal (with its sign), or
  // the fixed lattice normal of a box or node side (unit along one axis).
  struct GroupNormal {
    const float* field = nullptr;
    const double* values = nullptr;  // a per-sample condition: minus its gradient
    double sign = 0;
    int axis = -1;  // fixed normal: +-1 along axis
  };
  std::array<GroupNormal, kMaxConditions + 6> group_normal{};
  for (std::size_t g = 0; g < groups; ++g) {
    GroupNormal& gn = group_normal[g];
    if (g >= side_group) {
      const int side = static_cast<int>(g - side_group);
      gn.axis = side / 2;
      gn.sign = side % 2 == 0 ? -1.0 : 1.0;
    } else {
      const Condition& c = set.conditions[g];
      if (c.kind == ConditionKind::kBox) {
        gn.axis = c.axis;
        gn.sign = c.side == 0 ? -1.0 : 1.0;
      } else if (c.kind == ConditionKind::kSample) {
        gn.values = c.values.data();
        gn.sign = -1.0;  // inside where the condition grows
      } else if (c.kind != ConditionKind::kValidity) {
        gn.field = samples.fields[c.field].data();
        gn.sign = c.kind == ConditionKind::kLimitMin ? -1.0 : 1.0;
      }
    }
  }
  // Pass 1: each vertex's cell (clamped to the node), its fractions there and its
  // axis coordinates.
  scratch.cells.resize(nv);
  mesh.positions.resize(nv);
  // Whether a point strictly inside a cell rounded onto the cell's end: only then can two
  // lattice-distinct vertices share an axis position (collapsed_triangles.h). Checked
  // only where it may happen (above): the check is half of this loop's instructions.
  bool rounded_onto_sample = false;
  auto map_vertices = [&](auto check_rounding) {
    for (std::size_t v = 0; v < nv; ++v) {
      const Vec3& p = builder.points[v];
      CellPoint& cp = scratch.cells[v];
      std::size_t cell[3];
      auto& position = mesh.positions[v];
      for (int a = 0; a < 3; ++a) {
        const double lo = p[a] > 0 ? p[a] : 0.0;  // truncation = floor here
        std::size_t i = static_cast<std::size_t>(lo);
        if (i > dims[a] - 2) i = dims[a] - 2;
        cell[a] = i;
        const double f = p[a] - static_cast<double>(i);
        cp.f[a] = f;
        // The sample's own coordinate at either end of the cell (exact, as the
        // neighbouring node computes it), interpolated inside (selects, not branches:
        // which case applies varies from vertex to vertex).
        const auto& c = samples.coords[a];
        const double c0 = c[i], c1 = c[i + 1];
        const double inner = c0 + f * (c1 - c0);
        double at = f == 0.0 ? c0 : inner;
        at = f == 1.0 ? c1 : at;
        position[a] = at;
        if constexpr (decltype(check_rounding)::value) {
          rounded_onto_sample |= (f != 0.0) & (f != 1.0) & ((inner == c0) | (inner == c1));
        }
      }
      cp.index = (cell[2] * dims[1] + cell[1]) * dims[0] + cell[0];
      cp.cell = {static_cast<std::uint32_t>(cell[0]), static_cast<std::uint32_t>(cell[1]),
                 static_cast<std::uint32_t>(cell[2])};
    }
  };
  if (may_round) {
    map_vertices(std::true_type{});
  } else {
    map_vertices(std::false_type{});
  }
  // Pass 2: normals as covectors in axis coordinates (lattice gradient / spacing), unit
  // length (face normals where the gradient is zero or undefined, below).
  mesh.normals.resize(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    const CellPoint& cp = scratch.cells[v];
    const GroupNormal& gn = group_normal[builder.vertex_groups[v]];
    Vec3 n{0, 0, 0};
    if (gn.field != nullptr) {
      const Trilinear t = trilinear(gn.field, dims, cp, true);
      for (int a = 0; a < 3; ++a) n[a] = gn.sign * t.gradient[a] * scratch.inverse_spacing[a][cp.cell[a]];
    } else if (gn.values != nullptr) {
      const Trilinear t = trilinear(gn.values, dims, cp, true);
      for (int a = 0; a < 3; ++a) n[a] = gn.sign * t.gradient[a] * scratch.inverse_spacing[a][cp.cell[a]];
    } else if (gn.axis >= 0) {
      const double value = gn.sign * scratch.inverse_spacing[gn.axis][cp.cell[gn.axis]];
      for (int a = 0; a < 3; ++a) n[a] = a == gn.axis ? value : 0.0;  // no indexed store
    }
    const double len = std::sqrt(dot(n, n));
    if (!(len > 0) || !std::isfinite(len)) {
      scratch.needs_fallback[v] = 1;
      any_fallback = true;
    } else {
      const double inv = 1.0 / len;
      mesh.normals[v] = {static_cast<float>(n[0] * inv), static_cast<float>(n[1] * inv),
                         static_cast<float>(n[2] * inv)};
    }
  }
  // Pass 3: attributes.
  for (std::size_t a = 0; a < attribute_data.size(); ++a) {
    auto& out = mesh.attributes[a];
    out.resize(nv);
    for (std::size_t v = 0; v < nv; ++v) {
      out[v] = static_cast<float>(trilinear(attribute_data[a], dims, scratch.cells[v], false).value);
    }
  }
  if (any_fallback) {
    // Area-weighted face normals in axis coordinates where a field gradient is zero or
    // undefined.
    scratch.fallback.assign(nv, Vec3{0, 0, 0});
    for (const auto& t : mesh.triangles) {
      if (!scratch.needs_fallback[t[0]] && !scratch.needs_fallback[t[1]] &&
          !scratch.needs_fallback[t[2]]) {
        continue;
      }
      const auto& p0 = mesh.positions[t[0]];
      const auto& p1 = mesh.positions[t[1]];
      const auto& p2 = mesh.positions[t[2]];
      const Vec3 n = cross(Vec3{p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]},
                           Vec3{p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]});
      for (std::uint32_t v : t) {
        for (int a = 0; a < 3; ++a) scratch.fallback[v][a] += n[a];
      }
    }
    for (std::size_t v = 0; v < nv; ++v) {
      if (!scratch.needs_fallback[v]) continue;
      Vec3 n = scratch.fallback[v];
      double len = std::sqrt(dot(n, n));
      if (!(len > 0) || !std::isfinite(len)) {
        n = {0, 0, 1};
        len = 1;
      }
      mesh.normals[v] = {static_cast<float>(n[0] / len), static_cast<float>(n[1] / len),
                         static_cast<float>(n[2] / len)};
    }
  }
  // Vertices the lattice keeps apart but axis coordinates merge, and sheets without
  // volume: where a limit has min = max, or surfaces pass through samples.
  bool equal_bounds = false;
  for (const ExtractLimit& limit : request.limits) equal_bounds = equal_bounds || limit.min == limit.max;
  const bool sheets = equal_bounds || corner_crossings != corner_crossings_before;
  // The general clipper's points on the line where two conditions meet (two box planes:
  // a domain box's vertical edge) come from different lattice elements and can differ by
  // an ulp on the lattice while mapping to one axis position (54 zero-area triangles on a
  // box with a limit over three axes at level 1, robustness case box-on-integer-hpa).
  const bool clipped = local.clipped_tets > 0;
  if (sheets || rounded_onto_sample || clipped) remove_collapsed_triangles(mesh, sheets);
  // Rounding onto samples, and the clipper's points along such a line, can also leave three
  // distinct vertices on one line.
  if (rounded_onto_sample || clipped) split_collinear_slivers(mesh);
  if (stats) *stats = local;
  return mesh;
}

}  // namespace strielad
