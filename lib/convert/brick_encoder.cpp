// SPDX-License-Identifier: Apache-2.0
#include "convert/brick_encoder.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <type_traits>

#include "core/checksum.h"
#include "store/brick_codec.h"
#include "store/fpzip_chunk.h"
#include "store/zfp_chunk.h"

namespace strielad::build {

void NodeStats::merge(const NodeStats& o) {
  valid_count += o.valid_count;
  if (std::isnan(o.min)) return;
  if (std::isnan(min) || o.min < min) min = o.min;
  if (std::isnan(max) || o.max > max) max = o.max;
}

namespace {

template <typename T>
using Bits = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;

template <typename T>
using SignedBits = std::make_signed_t<Bits<T>>;

// An order-preserving signed-integer key of a floating-point value: a < b implies
// key(a) < key(b) (with -0 just below +0). Its own inverse. Integer min/max reductions
// vectorize where floating-point ones do not (GCC needs fast-math for those, which
// would also remove the NaN checks).
template <typename T>
SignedBits<T> order_key(SignedBits<T> bits) {
  constexpr int kShift = sizeof(T) * 8 - 1;
  return bits ^ ((bits >> kShift) & std::numeric_limits<SignedBits<T>>::max());
}

// Statistics over rows: min/max as order keys, valid-sample count.
template <typename T>
struct RowStats {
  SignedBits<T> min_key = std::numeric_limits<SignedBits<T>>::max();
  SignedBits<T> max_key = std::numeric_limits<SignedBits<T>>::min();
  std::uint64_t valid = 0;
  T min() const { return std::bit_cast<T>(order_key<T>(min_key)); }
  T max() const { return std::bit_cast<T>(order_key<T>(max_key)); }
};

// All ones when the bits of a T are not a NaN, else zero: a sample is NaN exactly when
// its magnitude bits exceed those of infinity. In integer bits, because a
// floating-point `v == v` in a loop keeps GCC 12 from vectorizing it.
template <typename T>
SignedBits<T> valid_mask(SignedBits<T> b) {
  using K = SignedBits<T>;
  constexpr K kMagnitude = std::numeric_limits<K>::max();
  constexpr K kInfinity = std::bit_cast<K>(std::numeric_limits<T>::infinity());
  return (b & kMagnitude) <= kInfinity ? K(-1) : K(0);
}

// Adds n samples to `stats`. Branch-free, on locals and integer bits only, so that GCC
// 12 vectorizes it; a NaN's key becomes a value that cannot win the min or the max.
template <typename T>
void scan_row(const T* row, std::size_t n, RowStats<T>& stats) {
  using K = SignedBits<T>;
  K mn = stats.min_key, mx = stats.max_key;
  K valid = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const K b = std::bit_cast<K>(row[i]);
    const K ok = valid_mask<T>(b);
    const K k = order_key<T>(b);
    valid -= ok;
    const K lo = (k & ok) | (std::numeric_limits<K>::max() & ~ok);
    const K hi = (k & ok) | (std::numeric_limits<K>::min() & ~ok);
    mn = lo < mn ? lo : mn;
    mx = hi > mx ? hi : mx;
  }
  stats.min_key = mn;
  stats.max_key = mx;
  stats.valid += static_cast<std::uint64_t>(valid);
}

// Samples that are not NaN, in integer bits for the same reason.
template <typename T>
std::uint64_t count_valid(const T* row, std::size_t n) {
  using K = SignedBits<T>;
  K valid = 0;
  for (std::size_t i = 0; i < n; ++i) valid -= valid_mask<T>(std::bit_cast<K>(row[i]));
  return static_cast<std::uint64_t>(valid);
}

// Samples equal to zero (either sign), in integer bits so that it vectorizes.
template <typename T>
std::size_t count_zeros(std::span<const T> samples) {
  using K = SignedBits<T>;
  std::size_t zeros = 0;
  for (const T v : samples) {
    zeros += (std::bit_cast<K>(v) & std::numeric_limits<K>::max()) == 0 ? 1 : 0;
  }
  return zeros;
}

// The chunk of a data brick of a variable with fpzip on: fpzip, the Blosc chain, or the
// smaller of both. Trying both on every brick costs about 4x the Blosc chain's time
// (fpzip codes ~130 MB/s per core), so the brick's share of zeros decides which to try
// (BENCHMARKS.md, "fpzip trials by a brick's share of zeros"): where few samples are zero fpzip
// nearly always wins and is kept alone when it halves the brick at least; where most
// are zero the Blosc chain's runs nearly always win; in between both are tried.
template <typename T>
std::vector<std::byte> encode_fpzip_or_blosc(std::span<const T> samples, const BrickDims& dims,
                                             const format::CodecSpec& codec,
                                             format::ChunkCoding& coding) {
  const std::span<const std::byte> raw = std::as_bytes(samples);
  constexpr DType dtype = kDTypeOf<T>;
  const double zero_share = static_cast<double>(count_zeros(samples)) / static_cast<double>(samples.size());
  coding = format::ChunkCoding::kCodec;
  if (zero_share >= kFpzipTriedBelowZeroShare) return compress_brick(raw, dtype, dims, codec);
  auto f = compress_brick_fpzip(raw, dtype, dims);
  if (f && zero_share < kFpzipAloneBelowZeroShare && 2 * f->size() <= raw.size()) {
    coding = format::ChunkCoding::kFpzip;
    return std::move(*f);
  }
  std::vector<std::byte> blosc = compress_brick(raw, dtype, dims, codec);
  if (f && f->size() < blosc.size()) {
    coding = format::ChunkCoding::kFpzip;
    return std::move(*f);
  }
  return blosc;
}

// The chunk of a data brick of a lossy variable: the zfp chunk when it keeps the bound and
// is smaller than the codec chain's, else the codec chain's (lossless). On mostly-zero
// bricks of sparse fields the chain's runs often beat zfp, and then it is both smaller and
// exact (BENCHMARKS.md, "lossy").
template <typename T>
std::vector<std::byte> encode_zfp_or_blosc(std::span<const T> samples, const BrickDims& dims,
                                           const format::CodecSpec& codec, EncodedBrick& out) {
  const std::span<const std::byte> raw = std::as_bytes(samples);
  const double bound = codec.zfp->tolerance;
  ZfpCodingResult z;
  for (const double multiple : kZfpAccuracyLadder) {
    z = compress_brick_zfp(raw, kDTypeOf<T>, dims, bound, multiple * bound);
    if (z.outcome != ZfpOutcome::kBoundExceeded) break;
  }
  out.lossy_fallback = z.outcome == ZfpOutcome::kBoundExceeded;
  std::vector<std::byte> chain = compress_brick(raw, kDTypeOf<T>, dims, codec);
  if (z.outcome == ZfpOutcome::kCoded && z.chunk.size() < chain.size()) {
    out.entry.coding = format::ChunkCoding::kZfp;
    return std::move(z.chunk);
  }
  return chain;
}

}  // namespace

template <typename T>
EncodedBrick encode_brick(const PlaneBlock<T>& planes, const IndexBox& box, const IndexBox* owned,
                          NodeStats stats, const format::CodecSpec& codec) {
  const std::size_t n = box.extent(0);
  // Per-thread scratch, never zero-filled: every sample is copied in below.
  static thread_local std::unique_ptr<T[]> scratch;
  static thread_local std::size_t scratch_size = 0;
  if (scratch_size < box.count()) {
    scratch.reset(new T[box.count()]);
    scratch_size = box.count();
  }
  const std::span<T> samples(scratch.get(), box.count());
  RowStats<T> covered;
  std::uint64_t owned_valid = 0;
  T* dst = samples.data();
  for (std::size_t z = box.lo[2]; z <= box.hi[2]; ++z) {
    for (std::size_t y = box.lo[1]; y <= box.hi[1]; ++y, dst += n) {
      const T* row = &planes.at(box.lo[0], y, z);
      std::memcpy(dst, row, n * sizeof(T));
      if (!owned) continue;
      scan_row<T>(row, n, covered);
      if (z >= owned->lo[2] && z <= owned->hi[2] && y >= owned->lo[1] && y <= owned->hi[1]) {
        const std::size_t end = owned->hi[0] - box.lo[0] + 1;
        const std::size_t begin = owned->lo[0] - box.lo[0];
        owned_valid += count_valid<T>(row + begin, end - begin);
      }
    }
  }
  if (owned) {
    stats = NodeStats{};
    stats.valid_count = owned_valid;
    if (covered.valid > 0) {
      stats.min = static_cast<double>(covered.min());
      stats.max = static_cast<double>(covered.max());
    }
  } else {
    // Above level 0 the range covers the brick's own samples too: one that stands in for
    // fill is a mean of level-below samples that may lie just outside the node's box
    // (formats/store.md, "Per-node statistics"), so culling by the range stays safe.
    scan_row<T>(samples.data(), samples.size(), covered);
    if (covered.valid > 0) {
      stats.merge(NodeStats{static_cast<double>(covered.min()),
                            static_cast<double>(covered.max()), 0});
    }
  }

  EncodedBrick out;
  out.entry.valid_count = stats.valid_count;
  out.entry.min = stats.min;
  out.entry.max = stats.max;

  // Kind: all missing, all bitwise equal (and valid), or data. `covered` has counted the
  // valid samples of the whole brick at every level; the equality scan stops early.
  const Bits<T> first = std::bit_cast<Bits<T>>(samples.front());
  const bool any_valid = covered.valid > 0;
  const bool all_equal = std::all_of(samples.begin(), samples.end(), [first](T v) {
    return std::bit_cast<Bits<T>>(v) == first;
  });
  if (!any_valid) {
    out.entry.kind = format::BrickKind::kEmpty;
  } else if (all_equal) {
    out.entry.kind = format::BrickKind::kConstant;
    out.entry.constant = static_cast<double>(samples.front());
  } else {
    out.entry.kind = format::BrickKind::kData;
    const BrickDims dims{box.extent(0), box.extent(1), box.extent(2)};
    if (codec.zfp) {  // store version 6
      out.chunk = encode_zfp_or_blosc<T>(samples, dims, codec, out);
    } else if (codec.fpzip) {  // store version 3
      out.chunk = encode_fpzip_or_blosc<T>(samples, dims, codec, out.entry.coding);
    } else {
      out.chunk = compress_brick(std::as_bytes(samples), kDTypeOf<T>, dims, codec);
    }
    out.entry.chunk_size = static_cast<std::uint32_t>(out.chunk.size());
    out.entry.chunk_checksum = checksum64(out.chunk);
  }
  return out;
}

template EncodedBrick encode_brick<float>(const PlaneBlock<float>&, const IndexBox&,
                                          const IndexBox*, NodeStats, const format::CodecSpec&);
template EncodedBrick encode_brick<double>(const PlaneBlock<double>&, const IndexBox&,
                                           const IndexBox*, NodeStats, const format::CodecSpec&);

}  // namespace strielad::build
