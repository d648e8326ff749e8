// SPDX-License-Identifier: Apache-2.0
#include "store/fpzip_chunk.h"

#include <fpzip.h>

#include <cstring>
#include <memory>

#include "core/byte_io.h"
#include "core/checksum.h"
#include "core/error.h"
#include "store/brick_stream.h"
#include "store/fpzip_stream_check.h"

namespace strielad {
namespace {

// The fpzip codec whose decoding check_fpzip_stream walks (fpzip 1.3).
constexpr unsigned kWalkedFpzipCodec = 0x0110;

struct WriterClose {
  void operator()(FPZ* f) const { fpzip_write_close(f); }
};
struct ReaderClose {
  void operator()(FPZ* f) const { fpzip_read_close(f); }
};

void describe_brick(FPZ* f, DType dtype, BrickDims dims) {
  f->type = dtype == DType::kFloat64 ? FPZIP_TYPE_DOUBLE : FPZIP_TYPE_FLOAT;
  f->prec = 0;  // full precision: lossless
  f->nx = static_cast<int>(dims[0]);
  f->ny = static_cast<int>(dims[1]);
  f->nz = static_cast<int>(dims[2]);
  f->nf = 1;
}

// fpzip reads and writes samples as float or double: they must be 8-byte aligned.
bool is_aligned(const void* p) { return reinterpret_cast<std::uintptr_t>(p) % 8 == 0; }

// The stream checksum (store/brick_stream.h) is no defence against a crafted chunk;
// check_fpzip_stream is.
std::uint64_t stream_checksum(std::span<const std::byte> stream, DType dtype, BrickDims dims) {
  return brick_stream_checksum(stream, dtype, dims, kFpzipStreamSeed);
}

}  // namespace

std::optional<std::vector<std::byte>> compress_brick_fpzip(std::span<const std::byte> samples,
                                                           DType dtype, BrickDims dims) {
  if (samples.size() != brick_bytes(dtype, dims)) {
    throw make_error(ErrorCode::kInternal, "compress_brick_fpzip: {} bytes for a {}x{}x{} brick of {}",
                     samples.size(), dims[0], dims[1], dims[2], dtype_name(dtype));
  }
  for (const std::size_t side : dims) {
    if (side == 0 || side > kMaxFpzipBrickSide) return std::nullopt;  // a reader rejects it
  }
  // A chunk larger than the raw samples is of no use.
  std::vector<std::byte> chunk(kFpzipChunkHeaderSize + samples.size());
  std::vector<std::uint64_t> copy;
  const void* values = samples.data();
  if (!is_aligned(values)) {
    copy.resize((samples.size() + 7) / 8);
    std::memcpy(copy.data(), samples.data(), samples.size());
    values = copy.data();
  }
  std::size_t n = 0;
  {
    std::unique_ptr<FPZ, WriterClose> f(
        fpzip_write_to_buffer(chunk.data() + kFpzipChunkHeaderSize, samples.size()));
    if (!f) throw make_error(ErrorCode::kInternal, "fpzip_write_to_buffer failed");
    describe_brick(f.get(), dtype, dims);
    n = fpzip_write(f.get(), values);
  }
  if (n == 0) return std::nullopt;  // did not fit: buffer overflow
  chunk.resize(kFpzipChunkHeaderSize + n);
  ByteWriter header;
  header.u64(checksum64(samples));
  header.u64(stream_checksum(std::span(chunk).subspan(kFpzipChunkHeaderSize), dtype, dims));
  std::memcpy(chunk.data(), header.data().data(), kFpzipChunkHeaderSize);
  return chunk;
}

void decompress_brick_fpzip(std::span<const std::byte> chunk, DType dtype, BrickDims dims,
                            std::span<std::byte> out, std::string_view what) {
  if (out.size() != brick_bytes(dtype, dims)) {
    throw make_error(ErrorCode::kInternal,
                     "decompress_brick_fpzip: {} bytes of output for a {}x{}x{} brick of {}",
                     out.size(), dims[0], dims[1], dims[2], dtype_name(dtype));
  }
  if (chunk.size() <= kFpzipChunkHeaderSize) {
    throw make_error(ErrorCode::kCorrupt, "{}: fpzip chunk of {} bytes is shorter than its header",
                     what, chunk.size());
  }
  ByteReader header(chunk, what);
  const std::uint64_t samples_sum = header.u64("samples_checksum");
  const std::uint64_t stream_sum = header.u64("stream_checksum");
  const std::span<const std::byte> stream = chunk.subspan(kFpzipChunkHeaderSize);
  if (stream_checksum(stream, dtype, dims) != stream_sum) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: fpzip chunk's stream checksum does not match (damaged, or not a {}x{}x{} "
                     "brick of {})",
                     what, dims[0], dims[1], dims[2], dtype_name(dtype));
  }
  if ((fpzip_codec_version >> 8) != kWalkedFpzipCodec) {
    throw make_error(ErrorCode::kUnsupported,
                     "{}: fpzip codec {:#x} is not the one this reader checks streams for ({:#x})",
                     what, fpzip_codec_version >> 8, kWalkedFpzipCodec);
  }
  // fpzip bounds neither its reads nor its table lookups: it sees only streams it decodes
  // within their bytes and tables (formats/store.md, "What fpzip sees").
  const std::size_t walked = check_fpzip_stream(stream, dtype, dims, what);
  std::vector<std::uint64_t> copy;
  void* values = out.data();
  if (!is_aligned(values)) {
    copy.resize((out.size() + 7) / 8);
    values = copy.data();
  }
  std::size_t read = 0;
  {
    std::unique_ptr<FPZ, ReaderClose> f(fpzip_read_from_buffer(stream.data()));
    if (!f) throw make_error(ErrorCode::kInternal, "fpzip_read_from_buffer failed");
    describe_brick(f.get(), dtype, dims);
    read = fpzip_read(f.get(), values);
  }
  if (read != walked) {
    throw make_error(ErrorCode::kInternal,
                     "{}: fpzip read {} stream bytes where the check walked {} (of {})", what, read,
                     walked, stream.size());
  }
  if (!copy.empty()) std::memcpy(out.data(), copy.data(), out.size());
  if (checksum64(out) != samples_sum) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: fpzip chunk decodes to other samples than were written (an fpzip build "
                     "with other floating-point arithmetic?)",
                     what);
  }
}

}  // namespace strielad
