// SPDX-License-Identifier: Apache-2.0
// A hash of a mesh position by its exact bits, for welding vertices that are the same
// point (the extraction computes shared points bit for bit alike: tet_clipper.h).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace strielad {

struct PositionBitsHash {
  std::size_t operator()(const std::array<double, 3>& p) const noexcept {
    std::uint64_t b[3];
    std::memcpy(b, p.data(), sizeof b);
    return static_cast<std::size_t>((b[0] * 0x9E3779B97F4A7C15ull) ^ (b[1] * 0xC2B2AE3D27D4EB4Full) ^
                                    (b[2] * 0x165667B19E3779F9ull));
  }
};

// Per vertex, the first vertex at the same exact position: one id per position, in
// flat open addressing (no map node per vertex).
inline std::vector<std::uint32_t> first_vertex_at_each_position(
    const std::vector<std::array<double, 3>>& positions) {
  const std::size_t nv = positions.size();
  const std::size_t cap = std::bit_ceil(std::max<std::size_t>(16, 2 * nv));
  constexpr std::uint32_t kEmpty = UINT32_MAX;
  std::vector<std::uint32_t> first_at(cap, kEmpty);
  std::vector<std::uint32_t> id(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    std::size_t i = PositionBitsHash{}(positions[v]) & (cap - 1);
    while (first_at[i] != kEmpty && positions[first_at[i]] != positions[v]) i = (i + 1) & (cap - 1);
    if (first_at[i] == kEmpty) first_at[i] = static_cast<std::uint32_t>(v);
    id[v] = first_at[i];
  }
  return id;
}

}  // namespace strielad
