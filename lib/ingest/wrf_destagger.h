// SPDX-License-Identifier: Apache-2.0
// WRF's Arakawa C grid: U on west_east_stag, V on south_north_stag and W (PH, PHB) on
// bottom_top_stag have one sample more along that dimension than the mass points. Read
// as data they are destaggered onto the mass points: mass sample i along the staggered
// dimension is the mean of staggered samples i and i + 1, computed in double
// (0.5 * (a + b)); a missing (NaN) neighbour makes the mean missing. SlabReader applies
// this when a variable's dimension named "*_stag" is one longer than the grid's.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>

#include "grid/axis.h"

namespace strielad::ingest {

enum class StaggeredAxis { kNone, kZ, kY, kX };

// Which of a variable's last three dimensions (z, y, x), with `names` and `lengths`, is
// staggered on a grid of `grid`: kNone when they equal the grid's, the one named "*_stag"
// and one longer otherwise; nullopt when the shape fits neither (or two are staggered).
std::optional<StaggeredAxis> staggered_axis(const std::array<std::string, 3>& names,
                                            const std::array<std::size_t, 3>& lengths,
                                            const Dims3& grid);

// The shape (x, y, levels) read from the file for mass slab `slab` (x, y, levels).
Dims3 staggered_extent(const Dims3& slab, StaggeredAxis axis);

// `staggered` (staggered_extent(slab, axis) samples, x fastest) destaggered into `out`
// (slab.count() samples).
void destagger(std::span<const double> staggered, const Dims3& slab, StaggeredAxis axis,
               std::span<double> out);
void destagger(std::span<const double> staggered, const Dims3& slab, StaggeredAxis axis,
               std::span<float> out);

}  // namespace strielad::ingest
