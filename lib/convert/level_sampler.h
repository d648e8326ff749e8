// SPDX-License-Identifier: Apache-2.0
// Fill-aware sub-sampling of one octree level into the next (formats/store.md,
// "Octree"): sample c of the coarse level is the fine sample at min(2c, n-1) along each
// halved axis when that is valid, else the double-precision mean of the valid fine
// samples at offsets -1, 0, +1 along the halved axes, else missing (NaN).
// Accuracy of the mean of k <= 27 values v_i (docs/robustness.md, "Sums and means"): the
// sum is accumulated in double, so before the final rounding to T the error is at most
// (k + 1) * 2^-53 * sum|v_i| / k; it never overflows (float64 data near its maximum is
// summed again scaled by 2^-5).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace strielad::build {

// A block of whole xy-planes of a level grid: planes [z_begin, z_begin + dims[2]) of a
// grid that has `z_total` planes. x varies fastest.
template <typename T>
struct PlaneBlock {
  const T* values = nullptr;
  std::array<std::size_t, 3> dims{};  // x, y, planes held
  std::size_t z_begin = 0;
  std::size_t z_total = 0;

  const T& at(std::size_t x, std::size_t y, std::size_t z) const {
    return values[((z - z_begin) * dims[1] + y) * dims[0] + x];
  }
};

// Fills coarse planes [cz_begin, cz_end) of `coarse` (a full grid of `coarse_dims`)
// from `fine`, which must hold every fine plane those coarse planes look at.
// `halved[a]` says whether axis a is halved between the two levels.
template <typename T>
void downsample_planes(const PlaneBlock<T>& fine, std::array<bool, 3> halved,
                       std::vector<T>& coarse, std::array<std::size_t, 3> coarse_dims,
                       std::size_t cz_begin, std::size_t cz_end);

// Fine plane that coarse plane c is centred on.
inline std::size_t fine_center(std::size_t c, bool halved, std::size_t fine_n) {
  if (!halved) return c;
  const std::size_t f = 2 * c;
  return f < fine_n ? f : fine_n - 1;
}

extern template void downsample_planes<float>(const PlaneBlock<float>&, std::array<bool, 3>,
                                              std::vector<float>&, std::array<std::size_t, 3>,
                                              std::size_t, std::size_t);
extern template void downsample_planes<double>(const PlaneBlock<double>&, std::array<bool, 3>,
                                               std::vector<double>&, std::array<std::size_t, 3>,
                                               std::size_t, std::size_t);

}  // namespace strielad::build
