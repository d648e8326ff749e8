// SPDX-License-Identifier: Apache-2.0
#include "extract/cell_sweep.h"

#include <bit>
#include <cstdint>

#include "extract/cell_tables.h"

namespace strielad {

namespace {

// The sweep over masks of one width (Mask: std::uint16_t or std::uint64_t).
template <class Mask>
class CellSweep {
 public:
  CellSweep(const Mask* inside, const ConditionSet& set, const std::array<std::size_t, 3>& dims,
            NodeMeshScratch& scratch, CellKernel& kernel, ExtractStats& stats)
      : inside_(inside), all_(set.all), dims_(dims), scratch_(scratch), kernel_(kernel), stats_(stats) {}

  void run() {
    summarise_sample_rows();
    auto [col_or, col_and] = scratch_.columns<Mask>();
    col_or.resize(dims_[0]);
    col_and.resize(dims_[0]);
    col_or_ = col_or.data();
    col_and_ = col_and.data();
    const bool any_multi = mark_cells_crossed_by_several();
    for (std::size_t z = 0; z + 1 < dims_[2]; ++z) {
      for (std::size_t y = 0; y + 1 < dims_[1]; ++y) {
        // A row of cells: skip it whole when a condition fails on all four sample rows;
        // when every condition holds on all of them only its cells on the node boundary
        // have faces.
        const std::size_t r0 = z * dims_[1] + y;
        std::uint64_t row_or, row_and;
        row_summary(r0, row_or, row_and);
        if ((row_or & all_) != all_) continue;
        const int yz_boundary = (y == 0 ? 1 << 2 : 0) | (y + 2 == dims_[1] ? 1 << 3 : 0) |
                                (z == 0 ? 1 << 4 : 0) | (z + 2 == dims_[2] ? 1 << 5 : 0);
        if (row_and == all_) {
          inside_row(y, z, yz_boundary);
        } else {
          cut_row(y, z, yz_boundary, any_multi);
        }
      }
    }
  }

 private:
  // Per row of samples (y, z): the conditions that hold somewhere and everywhere on it.
  void summarise_sample_rows() {
    const std::size_t rows = dims_[1] * dims_[2];
    scratch_.row_or.resize(rows);
    scratch_.row_and.resize(rows);
    for (std::size_t r = 0; r < rows; ++r) {
      const Mask* row = inside_ + r * dims_[0];
      Mask o = 0, a = static_cast<Mask>(all_);  // narrow masks: all fits
      for (std::size_t x = 0; x < dims_[0]; ++x) {
        o |= row[x];
        a &= row[x];
      }
      scratch_.row_or[r] = o;
      scratch_.row_and[r] = a;
    }
  }

  // Per column of the row of cells starting at sample row r0: the conditions that hold
  // at one and at all of its four samples.
  void fill_columns(std::size_t r0) {
    const Mask* s0 = inside_ + r0 * dims_[0];
    const Mask* s1 = s0 + dims_[0];
    const Mask* s2 = s0 + dims_[0] * dims_[1];
    const Mask* s3 = s2 + dims_[0];
    for (std::size_t x = 0; x < dims_[0]; ++x) {
      col_or_[x] = s0[x] | s1[x] | s2[x] | s3[x];
      col_and_[x] = s0[x] & s1[x] & s2[x] & s3[x];
    }
  }

  // A row of cells (y, z) as its four sample rows summarise it: every condition holds
  // somewhere (else the row is skipped) and the conditions that hold everywhere.
  void row_summary(std::size_t r0, std::uint64_t& row_or, std::uint64_t& row_and) const {
    const std::size_t rr[4]{r0, r0 + 1, r0 + dims_[1], r0 + dims_[1] + 1};
    row_or = 0;
    row_and = all_;
    for (std::size_t r : rr) {
      row_or |= scratch_.row_or[r];
      row_and &= scratch_.row_and[r];
    }
  }

  // Cells crossed by several conditions (cut into tetrahedra): the cells crossed by one
  // condition beside them split the shared side along its diagonal, as the tetrahedra
  // do. Looked for only where two conditions can cross one row of cells. Whether any is.
  bool mark_cells_crossed_by_several() {
    const std::size_t cx = dims_[0] - 1, cy = dims_[1] - 1;
    const std::size_t rows = dims_[1] * dims_[2];
    bool any_multi = false;
    std::uint64_t holds_everywhere = all_;
    for (std::size_t r = 0; r < rows; ++r) holds_everywhere &= scratch_.row_and[r];
    if (std::popcount(all_ & ~holds_everywhere) >= 2) {
      scratch_.multi.assign(cx * cy * (dims_[2] - 1), 0);
      for (std::size_t z = 0; z + 1 < dims_[2]; ++z) {
        for (std::size_t y = 0; y + 1 < dims_[1]; ++y) {
          const std::size_t r0 = z * dims_[1] + y;
          std::uint64_t row_or, row_and;
          row_summary(r0, row_or, row_and);
          if ((row_or & all_) != all_ || std::popcount(all_ & ~row_and) < 2) continue;
          fill_columns(r0);
          for (std::size_t x = 0; x + 1 < dims_[0]; ++x) {
            if (((col_or_[x] | col_or_[x + 1]) & all_) != all_) continue;
            const std::uint64_t mixed = all_ & ~(col_and_[x] & col_and_[x + 1]);
            if ((mixed & (mixed - 1)) == 0) continue;
            scratch_.multi[(z * cy + y) * cx + x] = 1;
            any_multi = true;
          }
        }
      }
    }
    multi_ = scratch_.multi.data();
    return any_multi;
  }

  // A row of cells wholly inside: the faces of its cells on the node boundary.
  void inside_row(std::size_t y, std::size_t z, int yz_boundary) {
    stats_.inside_cells += dims_[0] - 1;
    for (std::size_t x = 0; x + 1 < dims_[0]; ++x) {
      const int boundary = yz_boundary | (x == 0 ? 1 : 0) | (x + 2 == dims_[0] ? 2 : 0);
      if (boundary == 0) continue;
      kernel_.set_inside_cell(x, y, z, boundary);
      kernel_.inside_cell_faces();
    }
  }

  // A row of cells the region's boundary may cross: each cell skipped, taken whole, or
  // cut by the table or per tetrahedron.
  void cut_row(std::size_t y, std::size_t z, int yz_boundary, bool any_multi) {
    const std::uint64_t all = all_;
    const std::size_t r0 = z * dims_[1] + y;
    const Mask* s0 = inside_ + r0 * dims_[0];
    const Mask* s1 = s0 + dims_[0];
    const Mask* s2 = s0 + dims_[0] * dims_[1];
    const Mask* s3 = s2 + dims_[0];
    fill_columns(r0);
    const Mask* col_or = col_or_;
    const Mask* col_and = col_and_;
    for (std::size_t x = 0; x + 1 < dims_[0]; ++x) {
      if (((col_or[x] | col_or[x + 1]) & all) != all) continue;  // a condition fails at every corner
      const std::uint64_t cell_and = col_and[x] & col_and[x + 1] & all;
      const int boundary = yz_boundary | (x == 0 ? 1 : 0) | (x + 2 == dims_[0] ? 2 : 0);
      if (cell_and == all) {
        ++stats_.inside_cells;
        if (boundary != 0) {
          kernel_.set_inside_cell(x, y, z, boundary);
          kernel_.inside_cell_faces();
        }
        continue;
      }
      ++stats_.cut_cells;
      kernel_.set_cell(x, y, z, boundary);
      const std::uint64_t masks[8]{s0[x], s0[x + 1], s1[x], s1[x + 1],
                                   s2[x], s2[x + 1], s3[x], s3[x + 1]};
      const std::uint64_t mixed = all & ~cell_and;
      if ((mixed & (mixed - 1)) == 0) {
        table_cell(x, y, z, boundary, std::countr_zero(mixed), masks, any_multi);
      } else {
        tetrahedra_cell(boundary, masks);
      }
    }
  }

  // A cell crossed by condition c alone: its loops by table, split along the diagonal
  // on the node's boundary and next to cells cut into tetrahedra.
  void table_cell(std::size_t x, std::size_t y, std::size_t z, int boundary, int c,
                  const std::uint64_t (&masks)[8], bool any_multi) {
    const CellTables& tables = cell_tables();
    int cell_bits = 0;
    for (int k = 0; k < 8; ++k) cell_bits |= static_cast<int>((masks[k] >> c) & 1) << k;
    int split = boundary;
    if (any_multi) split |= sides_beside_tetrahedra(x, y, z);
    split &= tables.crossed_sides[static_cast<std::size_t>(cell_bits)];
    ++stats_.table_cells;
    const std::size_t entry = static_cast<std::size_t>(cell_bits) * 64 + static_cast<std::size_t>(split);
    kernel_.cell_loops(static_cast<std::uint32_t>(c), tables.loops[entry]);
    if (boundary != 0) kernel_.side_caps(static_cast<std::uint32_t>(c), cell_bits);
  }

  // The sides of cell (x, y, z) shared with a cell crossed by several conditions.
  int sides_beside_tetrahedra(std::size_t x, std::size_t y, std::size_t z) const {
    const std::size_t cx = dims_[0] - 1, cy = dims_[1] - 1;
    const std::size_t cell = (z * cy + y) * cx + x;
    const std::size_t cz = cx * cy;
    const std::uint8_t* multi = multi_;
    return (x > 0 && multi[cell - 1] ? 1 : 0) | (x + 2 < dims_[0] && multi[cell + 1] ? 2 : 0) |
           (y > 0 && multi[cell - cx] ? 4 : 0) | (y + 2 < dims_[1] && multi[cell + cx] ? 8 : 0) |
           (z > 0 && multi[cell - cz] ? 16 : 0) | (z + 2 < dims_[2] && multi[cell + cz] ? 32 : 0);
  }

  // A cell crossed by several conditions: per tetrahedron, skipped, on the boundary
  // only, by its polygon when one condition crosses it, else by the general clipper.
  void tetrahedra_cell(int boundary, const std::uint64_t (&masks)[8]) {
    const std::uint64_t all = all_;
    for (int t = 0; t < 6; ++t) {
      const auto& tet = kTets[t];
      std::uint64_t t_and = all, t_or = 0;
      for (int k : tet) {
        t_and &= masks[k];
        t_or |= masks[k];
      }
      if ((t_or & all) != all) continue;
      if (t_and == all) {
        if (boundary != 0) kernel_.inside_tet(t);
        continue;
      }
      const std::uint64_t tet_mixed = all & ~t_and;
      if ((tet_mixed & (tet_mixed - 1)) == 0) {
        ++stats_.simple_tets;
        const int c = std::countr_zero(tet_mixed);
        int bits = 0;
        for (int k = 0; k < 4; ++k) bits |= static_cast<int>((masks[tet[k]] >> c) & 1) << k;
        kernel_.simple_tet(t, static_cast<std::uint32_t>(c), bits);
        continue;
      }
      ++stats_.clipped_tets;
      kernel_.clipped_tet(t, tet_mixed);
    }
  }

  const Mask* inside_;
  const std::uint64_t all_;
  const std::array<std::size_t, 3> dims_;
  NodeMeshScratch& scratch_;
  CellKernel& kernel_;
  ExtractStats& stats_;
  Mask* col_or_ = nullptr;
  Mask* col_and_ = nullptr;
  const std::uint8_t* multi_ = nullptr;
};

}  // namespace

void sweep_cells(const ConditionSet& set, const std::array<std::size_t, 3>& dims,
                 NodeMeshScratch& scratch, CellKernel& kernel, ExtractStats& stats) {
  if (set.narrow) {
    CellSweep<std::uint16_t>(set.inside16.data(), set, dims, scratch, kernel, stats).run();
  } else {
    CellSweep<std::uint64_t>(set.inside64.data(), set, dims, scratch, kernel, stats).run();
  }
}

}  // namespace strielad
