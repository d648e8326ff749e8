// SPDX-License-Identifier: Apache-2.0
// Blosc 1 compression of brick samples (formats/store.md, "Brick kinds"). Uses the
// context API, so it is safe to call from many threads at once.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "format/manifest.h"
#include "grid/axis.h"

namespace strielad {

std::vector<std::byte> compress_brick(std::span<const std::byte> samples, DType dtype,
                                      const format::CodecSpec& codec);

// Decompresses a chunk that must hold exactly `expected_bytes` of `dtype` samples.
// Throws kCorrupt with `what` (file, variable, node) when the chunk is malformed.
void decompress_brick(std::span<const std::byte> chunk, DType dtype, std::span<std::byte> out,
                      std::string_view what);

}  // namespace strielad
