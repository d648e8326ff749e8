// SPDX-License-Identifier: Apache-2.0
// The cell kernel of extract_node_mesh (node_extractor.h): the vertex and polygon work of
// one node's cells. Vertices on lattice corners and edges are found by lattice element
// (slots of the NodeMeshScratch), the rest by position (MeshBuilder). A cell crossed by
// one condition takes its loops from the marching table (cell_loops), a tetrahedron
// crossed by one condition its polygon (simple_tet), one crossed by several the general
// clipper (clipped_tet); faces on the node's boundary come with them, and the wholly
// inside squares of the node's sides are made into rectangles at the end
// (inside_rectangles).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include "extract/cell_tables.h"
#include "extract/conditions.h"
#include "extract/mesh_builder.h"
#include "extract/node_mesh_scratch.h"
#include "extract/tet_clipper.h"

namespace strielad {

// One extraction's kernel over the scratch's buffers: set_cell (or set_inside_cell)
// names the current cell, the other calls emit its faces.
class CellKernel {
 public:
  // side_group: the group of node side 0 (sides 0..5 take side_group + side); `s` begun
  // for this node (NodeMeshScratch::begin).
  CellKernel(NodeMeshScratch& s, const ConditionSet& set, const std::array<std::size_t, 3>& dims,
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
    const CellEdge& ce = cell_tables().edges[e];
    const std::size_t sp = sample(ce.p);
    Slot& slot = s_.lattice[slot_[ce.p] + static_cast<std::size_t>(ce.p ^ ce.q)];
    const std::uint32_t stamp = slab_stamp_[ce.p >> 2];
    if (slot.tag == (stamp | c)) return slot.vertex;
    const Condition& cond = set_.conditions[c];
    const Vec3 P = corner_pos(ce.p), Q = corner_pos(ce.q);
    const EdgeCrossing x = edge_crossing(P, Q, cond.value(sp), cond.value(sample(ce.q)),
                                         s_.corner_crossings);
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
    const EdgeCrossing x = edge_crossing(P, Q, cond.value(sample(p)), cond.value(sample(q)),
                                         s_.corner_crossings);
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
  void inside_rectangles(bool merge);

  // Rectangle [u0, u0 + w] x [v0, v0 + h] of lattice points on node side `side` (u, v
  // its first and second plane axes, as in side_slot()): the strip between its left and
  // right edges, with the strip's first triangle fanned from its upper right corner
  // through the bottom edge's points and its last fanned from its lower left corner
  // through the top edge's points. Counter-clockwise in (u, v) is outward on an upper
  // side.
  void rectangle(int side, std::size_t u0, std::size_t v0, std::size_t w, std::size_t h);

  // One tetrahedron whose only crossing condition is c (bits: c's inside bits of its
  // corners, 1..14): the polygon on c's plane and its faces on the node boundary.
  void simple_tet(int t, std::uint32_t c, int bits) {
    const CellTables& tb = cell_tables();
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
    const CellTables& tb = cell_tables();
    for (int side = 0; side < 6; ++side) {
      if (!(boundary_ & (1 << side))) continue;
      const auto& quad = tb.side_quads[side];
      const int face_bits = (1 << quad[0]) | (1 << quad[1]) | (1 << quad[2]) | (1 << quad[3]);
      if ((bits & face_bits) == face_bits) {  // the whole face
        mark_inside_square(side);
        continue;
      }
      for (const std::array<int, 3>& tri : CellTables::side_triangles(quad)) {
        const std::array<bool, 3> in{((bits >> tri[0]) & 1) != 0, ((bits >> tri[1]) & 1) != 0,
                                     ((bits >> tri[2]) & 1) != 0};
        side_triangle_part(side, c, tri, in, false);
      }
    }
  }

  // A tetrahedron wholly inside: its faces on the node boundary.
  void inside_tet(int t) {
    const CellTables& tb = cell_tables();
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
  void clipped_tet(int t, std::uint64_t conditions);

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

  NodeMeshScratch& s_;
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

}  // namespace strielad
