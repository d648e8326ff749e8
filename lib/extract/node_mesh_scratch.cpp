// SPDX-License-Identifier: Apache-2.0
#include "extract/node_mesh_scratch.h"
#include "extract/thread_scratch.h"

#include <algorithm>

namespace strielad {

void NodeMeshScratch::begin(std::size_t samples, const std::array<std::size_t, 3>& dims) {
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
  corner_crossings = 0;
  builder.reset();
}

ExtractScratch& this_thread_scratch() {
  thread_local ExtractScratch scratch;
  return scratch;
}

}  // namespace strielad
