// SPDX-License-Identifier: Apache-2.0
// zfp chunks (formats/store.md, "zfp chunks"): a brick's samples coded by zfp (libzfp 1.0)
// in fixed-accuracy mode, error-bounded and lossy. zfp cannot code NaN, so missing samples
// are replaced by the brick's valid mean for coding and their positions kept in the chunk
// (a run list); the decoder puts the quiet NaN back there. zfp's tolerance is not a strict
// guarantee, so the writer decodes every chunk it codes and keeps it only when each valid
// sample lies within the bound; a reader checks the decoded samples against the checksum of
// what the writer verified. Safe to call from many threads at once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "grid/axis.h"
#include "store/lorenzo_predictor.h"

namespace strielad {

// Bytes of the chunk header before the missing-sample runs and the zfp stream.
inline constexpr std::size_t kZfpChunkHeaderSize = 32;

// What compress_brick_zfp made of a brick.
enum class ZfpOutcome {
  kCoded,          // `chunk` holds a zfp chunk within the bound, smaller than the raw brick
  kBoundExceeded,  // some valid sample decodes further than the bound (or is not finite)
  kNotSmaller,     // within the bound, but no smaller than the brick's raw bytes
};

struct ZfpCodingResult {
  ZfpOutcome outcome = ZfpOutcome::kBoundExceeded;
  std::vector<std::byte> chunk;  // only when kCoded
  double max_error = 0;          // over the valid samples, as decoded (when zfp coded it)
};

// Codes a brick of dims[0] x dims[1] x dims[2] samples (x fastest) of `dtype`; `samples`
// must hold exactly the brick's bytes, missing samples as NaN. `bound` is the guaranteed
// absolute error of every valid sample (> 0, finite); `accuracy` the tolerance handed to
// zfp's fixed-accuracy mode: the converter tries multiples of `bound` in turn
// (build::kZfpAccuracyLadder), tests larger ones that want the bound exceeded.
ZfpCodingResult compress_brick_zfp(std::span<const std::byte> samples, DType dtype, BrickDims dims,
                                   double bound, double accuracy);

// Decodes a zfp chunk into `out` (exactly the brick's bytes): valid samples within the
// bound the writer verified, missing ones as the dtype's quiet NaN. Throws kCorrupt with
// `what` (file, variable, node) when the chunk is shorter than its header, a checksum does
// not match, the zfp mode is not fixed accuracy, the runs do not cover the brick, or the
// stream does not decode to exactly its bytes.
void decompress_brick_zfp(std::span<const std::byte> chunk, DType dtype, BrickDims dims,
                          std::span<std::byte> out, std::string_view what);

}  // namespace strielad
