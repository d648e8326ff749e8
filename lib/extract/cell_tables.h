// SPDX-License-Identifier: Apache-2.0
// The fixed tables of the cell kernel (cell_kernel.h): the Kuhn split of a cell into six
// tetrahedra, each tetrahedron's polygon on a condition's plane and its faces on the cell's
// sides, and the marching table of closed loops for a cell crossed by one condition.
// Built once, on first use.
#pragma once

#include <array>
#include <cstdint>

namespace strielad {

// The six Kuhn tetrahedra of a cell: corners as cube indices (bit 0 x, 1 y, 2 z), in
// ascending order, which is also ascending sample order.
inline constexpr std::array<std::array<int, 4>, 6> kTets{{{0, 1, 3, 7},
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

struct CellTables {
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

  CellTables();

  // A side's two Kuhn triangles (split along its min-max diagonal), outward order.
  static std::array<std::array<int, 3>, 2> side_triangles(const std::array<int, 4>& q) {
    return {{{q[0], q[1], q[2]}, {q[0], q[2], q[3]}}};
  }
};

// The tables, built on the first call (thread-safe).
inline const CellTables& cell_tables() {
  static const CellTables t;
  return t;
}

}  // namespace strielad
