// SPDX-License-Identifier: Apache-2.0
#include "extract/cell_kernel.h"

namespace strielad {

void CellKernel::inside_rectangles(bool merge) {
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

void CellKernel::rectangle(int side, std::size_t u0, std::size_t v0, std::size_t w, std::size_t h) {
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

void CellKernel::clipped_tet(int t, std::uint64_t conditions) {
  const CellTables& tb = cell_tables();
  const auto& tet = kTets[t];
  const std::array<std::size_t, 4> ids{sample(tet[0]), sample(tet[1]), sample(tet[2]),
                                       sample(tet[3])};
  const std::array<Vec3, 4> pos{corner_pos(tet[0]), corner_pos(tet[1]), corner_pos(tet[2]),
                                corner_pos(tet[3])};
  TetClipper& clipper = s_.clipper;
  if (!clipper.clip(ids, pos, set_, conditions, s_.corner_crossings)) return;
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

}  // namespace strielad
