// SPDX-License-Identifier: Apache-2.0
// A hash of a mesh position by its exact bits, for welding vertices that are the same
// point (the extraction computes shared points bit for bit alike: tet_clipper.h).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace strielad {

struct PositionBitsHash {
  std::size_t operator()(const std::array<double, 3>& p) const noexcept {
    std::uint64_t b[3];
    std::memcpy(b, p.data(), sizeof b);
    return static_cast<std::size_t>((b[0] * 0x9E3779B97F4A7C15ull) ^ (b[1] * 0xC2B2AE3D27D4EB4Full) ^
                                    (b[2] * 0x165667B19E3779F9ull));
  }
};

}  // namespace strielad
