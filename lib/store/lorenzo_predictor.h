// SPDX-License-Identifier: Apache-2.0
// The `lorenzo3` predictor of formats/store.md ("Predictors"): the residual of the 3-D
// Lorenzo predictor over a brick's samples taken as unsigned integers of their own width
// (the IEEE bit patterns), with wrapping arithmetic, stored zigzag-mapped (0, -1, 1, -2
// ... -> 0, 1, 2, 3 ...). The residual equals Δx Δy Δz of the samples with zero padding,
// so it is exactly invertible whatever the bits hold (NaN payloads, signed zeros,
// infinities, denormals) and needs no floating-point rounding.
//
// Buffers are raw bytes (the caller's float32/float64 samples): they are accessed through
// may_alias integer types, so no float/integer aliasing rule is broken.
#pragma once

#include <array>
#include <cstddef>

namespace strielad {

// Samples along x, y, z (x fastest); every extent must be at least 1.
using BrickDims = std::array<std::size_t, 3>;

// Writes the zigzag-mapped residual of `in` to `out` (word_size 4 or 8 bytes per sample;
// both buffers hold dims[0] * dims[1] * dims[2] samples and must not overlap). One
// vectorizable pass.
void lorenzo3_encode(const std::byte* in, std::byte* out, BrickDims dims, std::size_t word_size);

// Turns a residual back into the samples, in place: per row one running sum along x of
// the un-zigzagged residual plus the row above, then per plane the plane below.
void lorenzo3_decode(std::byte* data, BrickDims dims, std::size_t word_size);

}  // namespace strielad
