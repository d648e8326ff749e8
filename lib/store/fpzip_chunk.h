// SPDX-License-Identifier: Apache-2.0
// fpzip chunks (formats/store.md, "fpzip chunks"): a brick's samples coded losslessly by
// fpzip (libfpzip), behind two checksums (of the stream, seeded with the brick's shape, and
// of the decoded samples: fpzip predicts in the platform's floating point). fpzip's decoder
// trusts its input, so a reader walks the stream first (check_fpzip_stream) and hands fpzip
// only streams it decodes within their bytes. Safe to call from many threads at once.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "grid/axis.h"
#include "store/lorenzo_predictor.h"

namespace strielad {

// Bytes of the chunk header before the fpzip stream (two XXH3 checksums).
inline constexpr std::size_t kFpzipChunkHeaderSize = 16;

// Codes a brick of dims[0] x dims[1] x dims[2] samples (x fastest) of `dtype`; `samples`
// must hold exactly the brick's bytes. Returns nullopt when fpzip cannot code it into at
// most the raw size (incompressible data): the caller keeps its other chunk.
std::optional<std::vector<std::byte>> compress_brick_fpzip(std::span<const std::byte> samples,
                                                           DType dtype, BrickDims dims);

// Decodes an fpzip chunk into `out` (exactly the brick's bytes). Throws kCorrupt with `what`
// (file, variable, node) when the chunk is too short, a checksum does not match, or the
// stream is not one fpzip can decode for this brick without reading past it or outside its
// tables (check_fpzip_stream); fpzip then never sees it.
void decompress_brick_fpzip(std::span<const std::byte> chunk, DType dtype, BrickDims dims,
                            std::span<std::byte> out, std::string_view what);

}  // namespace strielad
