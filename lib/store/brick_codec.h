// SPDX-License-Identifier: Apache-2.0
// Chunks of brick samples (formats/store.md, "Brick kinds" and "Predictors"): the
// codec's predictor applied to the samples, then one Blosc 1 buffer. Uses the Blosc
// context API and per-thread scratch space, so it is safe to call from many threads at
// once.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "format/manifest.h"
#include "grid/axis.h"
#include "store/lorenzo_predictor.h"

namespace strielad {

// Compresses a brick of dims[0] x dims[1] x dims[2] samples (x fastest) of `dtype` with
// the codec's predictor and Blosc settings (one Blosc block for the whole chunk).
// `samples` must hold exactly the brick's bytes. The predictor's residual goes to
// per-thread scratch: the only allocation is the returned chunk.
std::vector<std::byte> compress_brick(std::span<const std::byte> samples, DType dtype,
                                      BrickDims dims, const format::CodecSpec& codec);

// Decompresses a chunk of a brick of `dims` samples into `out` (exactly the brick's
// bytes) and undoes the codec's predictor in place. Throws kCorrupt with `what` (file,
// variable, node) when the chunk is malformed: not a Blosc buffer, another type size,
// another uncompressed size.
void decompress_brick(std::span<const std::byte> chunk, DType dtype, BrickDims dims,
                      const format::CodecSpec& codec, std::span<std::byte> out,
                      std::string_view what);

// The Blosc layer alone (predictor "none"), for callers that have no brick shape. The
// compressing one throws kInvalidArgument when `codec` names another predictor; the
// decompressing one returns what the chunk holds, which for a variable whose predictor
// is not "none" is the residual, not the samples.
std::vector<std::byte> compress_brick(std::span<const std::byte> samples, DType dtype,
                                      const format::CodecSpec& codec);
void decompress_brick(std::span<const std::byte> chunk, DType dtype, std::span<std::byte> out,
                      std::string_view what);

}  // namespace strielad
