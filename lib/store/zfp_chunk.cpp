// SPDX-License-Identifier: Apache-2.0
#include "store/zfp_chunk.h"

#include <zfp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

#include "core/byte_io.h"
#include "core/checksum.h"
#include "core/error.h"
#include "store/brick_stream.h"

namespace strielad {
namespace {

struct StreamClose {
  void operator()(zfp_stream* z) const { zfp_stream_close(z); }
};
struct BitstreamClose {
  void operator()(bitstream* s) const { stream_close(s); }
};
struct FieldFree {
  void operator()(zfp_field* f) const { zfp_field_free(f); }
};

zfp_type zfp_type_of(DType dtype) {
  return dtype == DType::kFloat64 ? zfp_type_double : zfp_type_float;
}

std::uint64_t stream_checksum(std::span<const std::byte> bytes, DType dtype, BrickDims dims) {
  return brick_stream_checksum(bytes, dtype, dims, kZfpStreamSeed);
}

void put_varint(std::vector<std::byte>& out, std::uint64_t v) {
  while (v >= 0x80) {
    out.push_back(static_cast<std::byte>((v & 0x7f) | 0x80));
    v >>= 7;
  }
  out.push_back(static_cast<std::byte>(v));
}

// The missing-sample runs: lengths of alternating runs of valid and missing samples in
// sample order, the first one valid (possibly 0), LEB128.
template <typename T>
std::vector<std::byte> missing_runs(std::span<const T> samples) {
  std::vector<std::byte> runs;
  bool missing = false;
  std::uint64_t run = 0;
  for (const T v : samples) {
    if (std::isnan(v) != missing) {
      put_varint(runs, run);
      missing = !missing;
      run = 0;
    }
    ++run;
  }
  if (missing) put_varint(runs, run);  // a trailing valid run is implied by the count
  return runs;
}

// Reads the runs into a mask (true = missing); kCorrupt unless they cover at most the
// brick and mark exactly `missing_count` samples missing.
std::vector<bool> read_runs(std::span<const std::byte> runs, std::size_t n,
                            std::uint64_t missing_count, std::string_view what) {
  std::vector<bool> mask(n, false);
  std::size_t pos = 0, i = 0;
  std::uint64_t missing_seen = 0;
  bool missing = false;
  while (i < runs.size()) {
    std::uint64_t v = 0;
    int shift = 0;
    for (;;) {
      if (i >= runs.size() || shift > 56) {
        throw make_error(ErrorCode::kCorrupt, "{}: zfp chunk's missing-sample runs are malformed",
                         what);
      }
      const auto b = static_cast<std::uint8_t>(runs[i++]);
      v |= std::uint64_t{b & 0x7fu} << shift;
      shift += 7;
      if ((b & 0x80) == 0) break;
    }
    if (v > n - pos) {
      throw make_error(ErrorCode::kCorrupt,
                       "{}: zfp chunk's missing-sample runs cover more than the brick's {} samples",
                       what, n);
    }
    if (missing) {
      std::fill(mask.begin() + static_cast<std::ptrdiff_t>(pos),
                mask.begin() + static_cast<std::ptrdiff_t>(pos + v), true);
      missing_seen += v;
    }
    pos += v;
    missing = !missing;
  }
  if (missing_seen != missing_count) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: zfp chunk's runs mark {} samples missing, its header {}", what,
                     missing_seen, missing_count);
  }
  return mask;
}

struct Zfp {
  std::unique_ptr<zfp_stream, StreamClose> stream{zfp_stream_open(nullptr)};
  std::unique_ptr<zfp_field, FieldFree> field;
  std::unique_ptr<bitstream, BitstreamClose> bits;
  Zfp(void* values, DType dtype, BrickDims dims)
      : field(zfp_field_3d(values, zfp_type_of(dtype), dims[0], dims[1], dims[2])) {
    if (!stream || !field) throw make_error(ErrorCode::kInternal, "zfp: out of memory");
  }
  void attach(void* buffer, std::size_t size) {
    bits.reset(stream_open(buffer, size));
    if (!bits) throw make_error(ErrorCode::kInternal, "zfp: out of memory");
    zfp_stream_set_bit_stream(stream.get(), bits.get());
    zfp_stream_rewind(stream.get());
  }
};

// The decoding both sides share: header fields checked, the stream decoded into `out`
// (missing samples as quiet NaN). Returns the header's samples checksum.
template <typename T>
std::uint64_t decode_chunk(std::span<const std::byte> chunk, BrickDims dims, std::span<T> out,
                           std::string_view what) {
  constexpr DType dtype = kDTypeOf<T>;
  if (chunk.size() <= kZfpChunkHeaderSize) {
    throw make_error(ErrorCode::kCorrupt, "{}: zfp chunk of {} bytes is shorter than its header",
                     what, chunk.size());
  }
  ByteReader header(chunk, what);
  const std::uint64_t samples_sum = header.u64("samples_checksum");
  const std::uint64_t stream_sum = header.u64("stream_checksum");
  const std::uint64_t mode = header.u64("zfp_mode");
  const std::uint32_t missing_count = header.u32("missing_count");
  const std::uint32_t runs_size = header.u32("runs_size");
  if (stream_checksum(chunk.subspan(16), dtype, dims) != stream_sum) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: zfp chunk's stream checksum does not match (damaged, or not a {}x{}x{} "
                     "brick of {})",
                     what, dims[0], dims[1], dims[2], dtype_name(dtype));
  }
  if (runs_size >= chunk.size() - kZfpChunkHeaderSize) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: zfp chunk's runs ({} bytes) leave no stream in its {} bytes", what,
                     runs_size, chunk.size());
  }
  const std::size_t n = out.size();
  const std::vector<bool> mask =
      read_runs(chunk.subspan(kZfpChunkHeaderSize, runs_size), n, missing_count, what);
  const std::span<const std::byte> stream = chunk.subspan(kZfpChunkHeaderSize + runs_size);

  Zfp z(out.data(), dtype, dims);
  if (zfp_stream_set_mode(z.stream.get(), mode) != zfp_mode_fixed_accuracy ||
      zfp_stream_mode(z.stream.get()) != mode) {
    throw make_error(ErrorCode::kCorrupt, "{}: zfp chunk's mode {:#x} is not a fixed-accuracy mode",
                     what, mode);
  }
  const std::size_t max_size = zfp_stream_maximum_size(z.stream.get(), z.field.get());
  if (stream.size() > max_size || stream.size() % (stream_word_bits / 8) != 0) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: zfp stream of {} bytes cannot be one of this brick (at most {}, whole "
                     "{}-bit words)",
                     what, stream.size(), max_size, stream_word_bits);
  }
  // zfp reads its stream without bounds, but no block makes it read more than its
  // exponent and, per bit plane of the block's integers, two bits per value and one more
  // (nor more than ZFP_MAX_BITS, every read counted against the block's budget): it gets a
  // copy of the stream in a zero-filled buffer of that many bits per block plus a word of
  // read-ahead, and must have read exactly the stream's bytes (formats/store.md, "What zfp
  // sees"). The buffer is the thread's, kept zero beyond the stream copied in.
  constexpr std::size_t kExponentBits = 1 + (sizeof(T) == 8 ? 11 : 8);
  constexpr std::size_t kBlockBits =
      std::min<std::size_t>(ZFP_MAX_BITS, kExponentBits + 8 * sizeof(T) * (2 * 64 + 1));
  const std::size_t blocks = ((dims[0] + 3) / 4) * ((dims[1] + 3) / 4) * ((dims[2] + 3) / 4);
  const std::size_t words = (blocks * kBlockBits + 63) / 64 + 1;
  static thread_local std::vector<std::uint64_t> padded;
  if (padded.size() < words) padded.assign(words, 0);
  struct Rezero {
    std::uint64_t* p;
    std::size_t n;
    ~Rezero() { std::memset(p, 0, n); }
  } rezero{padded.data(), stream.size()};
  std::memcpy(padded.data(), stream.data(), stream.size());
  z.attach(padded.data(), words * 8);
  const std::size_t read = zfp_decompress(z.stream.get(), z.field.get());
  if (read != stream.size()) {
    throw make_error(ErrorCode::kCorrupt, "{}: zfp stream of {} bytes decodes from {} bytes", what,
                     stream.size(), read);
  }
  for (std::size_t i = 0; missing_count > 0 && i < n; ++i) {
    if (mask[i]) out[i] = std::numeric_limits<T>::quiet_NaN();
  }
  return samples_sum;
}

template <typename T>
ZfpCodingResult compress(std::span<const T> samples, BrickDims dims, double bound, double accuracy) {
  constexpr DType dtype = kDTypeOf<T>;
  ZfpCodingResult result;
  const std::size_t n = samples.size();
  // zfp codes finite values only: missing samples become the valid mean for coding.
  long double sum = 0;
  std::size_t valid = 0, missing = 0;
  for (const T v : samples) {
    if (std::isnan(v)) {
      ++missing;
    } else if (!std::isfinite(v)) {
      return result;  // kBoundExceeded: an infinity zfp cannot code
    } else {
      sum += v;
      ++valid;
    }
  }
  if (valid == 0) return result;
  const T fill = static_cast<T>(sum / static_cast<long double>(valid));
  std::vector<T> filled(samples.begin(), samples.end());
  for (T& v : filled) v = std::isnan(v) ? fill : v;

  Zfp z(filled.data(), dtype, dims);
  zfp_stream_set_accuracy(z.stream.get(), accuracy);
  const std::size_t max_size = zfp_stream_maximum_size(z.stream.get(), z.field.get());
  std::vector<std::uint64_t> buffer((max_size + 7) / 8, 0);
  z.attach(buffer.data(), buffer.size() * 8);
  const std::size_t stream_size = zfp_compress(z.stream.get(), z.field.get());
  if (stream_size == 0) throw make_error(ErrorCode::kInternal, "zfp_compress failed");

  const std::vector<std::byte> runs = missing_runs(samples);
  ByteWriter w;
  w.u64(0);  // samples_checksum, below
  w.u64(0);  // stream_checksum, below
  w.u64(zfp_stream_mode(z.stream.get()));
  w.u32(static_cast<std::uint32_t>(missing));
  w.u32(static_cast<std::uint32_t>(runs.size()));
  w.bytes(runs);
  w.bytes(std::as_bytes(std::span(buffer)).first(stream_size));
  std::vector<std::byte> chunk = w.take();
  const std::uint64_t stream_sum = stream_checksum(std::span(chunk).subspan(16), dtype, dims);
  std::memcpy(chunk.data() + 8, &stream_sum, 8);  // little-endian hosts only (core/byte_io.h)

  // The guarantee: decode as a reader will, compare every valid sample.
  std::vector<T> decoded(n);
  decode_chunk<T>(chunk, dims, std::span(decoded), "zfp chunk being written");
  double max_error = 0;
  bool within = true;
  for (std::size_t i = 0; i < n; ++i) {
    const T o = samples[i], d = decoded[i];
    if (std::isnan(o)) continue;  // restored from the runs
    if (!std::isfinite(d)) {
      within = false;
      max_error = std::numeric_limits<double>::infinity();
      break;
    }
    const double e = std::abs(static_cast<double>(d) - static_cast<double>(o));
    max_error = std::max(max_error, e);
    within = within && e <= bound;
  }
  result.max_error = max_error;
  if (!within) return result;
  if (chunk.size() >= n * sizeof(T)) {
    result.outcome = ZfpOutcome::kNotSmaller;
    return result;
  }
  const std::uint64_t samples_sum = checksum64(std::as_bytes(std::span(decoded)));
  std::memcpy(chunk.data(), &samples_sum, 8);
  result.outcome = ZfpOutcome::kCoded;
  result.chunk = std::move(chunk);
  return result;
}

}  // namespace

ZfpCodingResult compress_brick_zfp(std::span<const std::byte> samples, DType dtype, BrickDims dims,
                                   double bound, double accuracy) {
  if (samples.size() != brick_bytes(dtype, dims)) {
    throw make_error(ErrorCode::kInternal, "compress_brick_zfp: {} bytes for a {}x{}x{} brick of {}",
                     samples.size(), dims[0], dims[1], dims[2], dtype_name(dtype));
  }
  if (!(bound > 0) || !std::isfinite(bound) || !(accuracy > 0) || !std::isfinite(accuracy)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "compress_brick_zfp: bound {} and accuracy {} must be positive and finite",
                     bound, accuracy);
  }
  if (dims[0] * dims[1] * dims[2] >= std::numeric_limits<std::uint32_t>::max()) {
    return {};  // the header counts samples in 32 bits: kBoundExceeded, the caller keeps its chunk
  }
  // Copies: the samples need not be aligned for T.
  if (dtype == DType::kFloat64) {
    std::vector<double> v(samples.size() / 8);
    std::memcpy(v.data(), samples.data(), samples.size());
    return compress<double>(v, dims, bound, accuracy);
  }
  std::vector<float> v(samples.size() / 4);
  std::memcpy(v.data(), samples.data(), samples.size());
  return compress<float>(v, dims, bound, accuracy);
}

void decompress_brick_zfp(std::span<const std::byte> chunk, DType dtype, BrickDims dims,
                          std::span<std::byte> out, std::string_view what) {
  if (out.size() != brick_bytes(dtype, dims)) {
    throw make_error(ErrorCode::kInternal,
                     "decompress_brick_zfp: {} bytes of output for a {}x{}x{} brick of {}",
                     out.size(), dims[0], dims[1], dims[2], dtype_name(dtype));
  }
  // In place where `out` is aligned for the sample type (a Brick's bytes are), else a copy.
  const auto decode = [&]<typename T>(T*) {
    if (reinterpret_cast<std::uintptr_t>(out.data()) % alignof(T) == 0) {
      return decode_chunk<T>(chunk, dims, std::span(reinterpret_cast<T*>(out.data()), out.size() / sizeof(T)), what);
    }
    std::vector<T> v(out.size() / sizeof(T));
    const std::uint64_t sum = decode_chunk<T>(chunk, dims, std::span(v), what);
    std::memcpy(out.data(), v.data(), out.size());
    return sum;
  };
  const std::uint64_t samples_sum = dtype == DType::kFloat64 ? decode(static_cast<double*>(nullptr))
                                                             : decode(static_cast<float*>(nullptr));
  if (checksum64(out) != samples_sum) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: zfp chunk decodes to other samples than the writer verified", what);
  }
}

}  // namespace strielad
