// SPDX-License-Identifier: Apache-2.0
#include "store/brick_codec.h"

#include <blosc.h>

#include <memory>

#include "core/error.h"

namespace strielad {

std::vector<std::byte> compress_brick(std::span<const std::byte> samples, DType dtype,
                                      const format::CodecSpec& codec) {
  const int shuffle = codec.shuffle == "bit"    ? BLOSC_BITSHUFFLE
                      : codec.shuffle == "byte" ? BLOSC_SHUFFLE
                                                : BLOSC_NOSHUFFLE;
  // Scratch space is reused per thread and never zero-filled: only the bytes Blosc
  // writes are copied out.
  static thread_local std::unique_ptr<std::byte[]> scratch;
  static thread_local std::size_t scratch_size = 0;
  const std::size_t need = samples.size() + BLOSC_MAX_OVERHEAD;
  if (scratch_size < need) {
    scratch.reset(new std::byte[need]);
    scratch_size = need;
  }
  const int n = blosc_compress_ctx(codec.level, shuffle, dtype_size(dtype), samples.size(),
                                   samples.data(), scratch.get(), need, codec.name.c_str(),
                                   /*blocksize=*/0, /*numinternalthreads=*/1);
  if (n <= 0) {
    throw make_error(ErrorCode::kInternal, "blosc compression with codec '{}' failed (code {})",
                     codec.name, n);
  }
  return std::vector<std::byte>(scratch.get(), scratch.get() + n);
}

void decompress_brick(std::span<const std::byte> chunk, DType dtype, std::span<std::byte> out,
                      std::string_view what) {
  std::size_t nbytes = 0;
  if (chunk.size() < BLOSC_MIN_HEADER_LENGTH ||
      blosc_cbuffer_validate(chunk.data(), chunk.size(), &nbytes) != 0) {
    throw make_error(ErrorCode::kCorrupt, "{}: chunk of {} bytes is not a valid Blosc buffer", what,
                     chunk.size());
  }
  if (nbytes != out.size()) {
    throw make_error(ErrorCode::kCorrupt, "{}: chunk holds {} bytes, the brick needs {}", what,
                     nbytes, out.size());
  }
  std::size_t typesize = 0;
  int flags = 0;
  blosc_cbuffer_metainfo(chunk.data(), &typesize, &flags);
  if (typesize != dtype_size(dtype)) {
    throw make_error(ErrorCode::kCorrupt, "{}: chunk has type size {}, the variable's is {}", what,
                     typesize, dtype_size(dtype));
  }
  const int n = blosc_decompress_ctx(chunk.data(), out.data(), out.size(), 1);
  if (n < 0 || static_cast<std::size_t>(n) != out.size()) {
    throw make_error(ErrorCode::kCorrupt, "{}: chunk does not decompress (blosc code {})", what, n);
  }
}

}  // namespace strielad
