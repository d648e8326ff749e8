// SPDX-License-Identifier: Apache-2.0
// The working memory of extract_node_mesh (node_extractor.h): condition masks, vertex
// slots, the mesh builder and the general clipper, kept by the caller across nodes so
// that a node costs no fresh pages (about 1 MB for 25^3 samples). One scratch serves one
// extraction at a time: a thread that extracts keeps its own.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "extract/conditions.h"
#include "extract/mesh_builder.h"
#include "extract/tet_clipper.h"

namespace strielad {

// A vertex remembered per lattice element (a corner or a lattice edge): tag = stamp
// << 8 | group, valid while the stamp is current.
struct Slot {
  std::uint32_t tag = 0;
  std::uint32_t vertex = 0;
};
inline constexpr std::uint32_t kStampLimit = 1u << 24;

// A lattice point's cell (clamped to the node) and its fractions there, for trilinear
// interpolation.
struct CellPoint {
  std::size_t index = 0;  // sample of the cell's corner 0
  double f[3]{};
  std::array<std::uint32_t, 3> cell{};
};

struct NodeMeshScratch {
  ConditionSet set;
  MeshBuilder builder;
  TetClipper clipper;
  // Crossings of this extraction put on a lattice corner (edge_crossing, tet_clipper.h):
  // only then can surfaces coincide (sheets without volume, collapsed_triangles.h), so
  // they are looked for only when this is not zero. Cleared by begin().
  std::uint64_t corner_crossings = 0;
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

  // Readies the buffers for a node of `samples` samples in `dims`: fresh stamps (every
  // slot of an earlier extraction stale), no inside squares, an empty builder.
  void begin(std::size_t samples, const std::array<std::size_t, 3>& dims);
};

}  // namespace strielad
