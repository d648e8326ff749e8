// SPDX-License-Identifier: Apache-2.0
#include "store/brick_stream.h"

#include <xxhash.h>

namespace strielad {

std::size_t brick_bytes(DType dtype, BrickDims dims) {
  return dims[0] * dims[1] * dims[2] * dtype_size(dtype);
}

std::uint64_t brick_stream_checksum(std::span<const std::byte> stream, DType dtype, BrickDims dims,
                                    std::uint64_t coding_seed) {
  const std::uint64_t seed = std::uint64_t{dims[0]} | std::uint64_t{dims[1]} << 20 |
                             std::uint64_t{dims[2]} << 40 |
                             std::uint64_t{dtype == DType::kFloat64 ? 1u : 0u} << 60 | coding_seed;
  return XXH3_64bits_withSeed(stream.data(), stream.size(), seed);
}

}  // namespace strielad
