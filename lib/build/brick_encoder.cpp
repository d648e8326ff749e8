// SPDX-License-Identifier: Apache-2.0
#include "build/brick_encoder.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <type_traits>

#include "core/checksum.h"
#include "store/brick_codec.h"

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
      // Branch-free, on locals and integer keys, so that it vectorizes.
      using K = SignedBits<T>;
      K mn = covered.min_key, mx = covered.max_key;
      std::uint32_t valid = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const T v = row[i];
        const bool ok = v == v;
        const K k = order_key<T>(std::bit_cast<K>(v));
        valid += ok;
        const K lo = ok ? k : std::numeric_limits<K>::max();
        const K hi = ok ? k : std::numeric_limits<K>::min();
        mn = lo < mn ? lo : mn;
        mx = hi > mx ? hi : mx;
      }
      covered.min_key = mn;
      covered.max_key = mx;
      covered.valid += valid;
      if (z >= owned->lo[2] && z <= owned->hi[2] && y >= owned->lo[1] && y <= owned->hi[1]) {
        const std::size_t end = owned->hi[0] - box.lo[0] + 1;
        std::uint32_t row_valid = 0;
        for (std::size_t i = owned->lo[0] - box.lo[0]; i < end; ++i) row_valid += row[i] == row[i];
        owned_valid += row_valid;
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
    NodeStats own;
    for (const T v : samples) {
      if (v != v) continue;
      const double d = static_cast<double>(v);
      if (!(own.min <= d)) own.min = d;  // NaN at first
      if (!(own.max >= d)) own.max = d;
    }
    stats.merge(own);
  }

  EncodedBrick out;
  out.entry.valid_count = stats.valid_count;
  out.entry.min = stats.min;
  out.entry.max = stats.max;

  // Kind: all missing, all bitwise equal (and valid), or data. Both scans stop early,
  // and level 0 already knows whether any sample is valid.
  const Bits<T> first = std::bit_cast<Bits<T>>(samples.front());
  const bool any_valid = owned ? covered.valid > 0
                               : std::any_of(samples.begin(), samples.end(),
                                             [](T v) { return v == v; });
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
    const std::span<const std::byte> raw(reinterpret_cast<const std::byte*>(samples.data()),
                                         samples.size() * sizeof(T));
    out.chunk = compress_brick(raw, sizeof(T) == 4 ? DType::kFloat32 : DType::kFloat64,
                               BrickDims{box.extent(0), box.extent(1), box.extent(2)}, codec);
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
