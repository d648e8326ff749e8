// SPDX-License-Identifier: Apache-2.0
// What the fpzip and zfp chunks (formats/store.md, "fpzip chunks", "zfp chunks") share:
// the size of a brick's raw samples, and the stream checksum seeded with the brick's shape
// and type, so that damage and a chunk filed under another brick show as a mismatch. It is
// no defence against a crafted chunk (anyone can recompute it).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "grid/axis.h"
#include "store/lorenzo_predictor.h"

namespace strielad {

// Bytes of a brick of dims[0] x dims[1] x dims[2] samples of `dtype`.
std::size_t brick_bytes(DType dtype, BrickDims dims);

// The coding's part of a stream checksum's seed: 0 for fpzip, 2^61 for zfp.
inline constexpr std::uint64_t kFpzipStreamSeed = 0;
inline constexpr std::uint64_t kZfpStreamSeed = std::uint64_t{1} << 61;

// XXH3-64 of `stream` with seed n_x + 2^20 n_y + 2^40 n_z + 2^60 t (t 0 for float32, 1 for
// float64) + `coding_seed`.
std::uint64_t brick_stream_checksum(std::span<const std::byte> stream, DType dtype, BrickDims dims,
                                    std::uint64_t coding_seed);

}  // namespace strielad
