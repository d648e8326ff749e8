// SPDX-License-Identifier: Apache-2.0
// An independent walk of fpzip 1.3's decoding (codec 0x0110): its 32-bit range decoder and
// the quasi-static frequency model its predictive coder reads residual classes with,
// written from the decoder's documented arithmetic, with every read bounded. It decodes
// no sample values: those need the floating-point predictor and do not steer the decoder.
#include "store/fpzip_stream_check.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "core/error.h"

namespace strielad {
namespace {

// fpzip's model: cumulative frequencies sum to 2^16, rescaled at most every 1024 symbols.
constexpr unsigned kFrequencyBits = 16;
constexpr std::uint32_t kFrequencyTotal = std::uint32_t{1} << kFrequencyBits;
constexpr std::uint32_t kLongestRescaleInterval = 1024;

// Symbol frequencies that adapt to the symbols decoded so far, exactly as fpzip's model
// does: halved and redistributed at growing intervals, cumulative counts refreshed only
// then. Which symbol a cumulative frequency falls into thus depends on the history alone.
class AdaptiveFrequencies {
 public:
  struct Interval {
    unsigned symbol;
    std::uint32_t start;  // cumulative frequency of the symbols below
    std::uint32_t size;   // the symbol's frequency, at least 1
  };

  explicit AdaptiveFrequencies(unsigned symbols)
      : frequency_(symbols), cumulative_(symbols + 1), rescale_interval_((symbols >> 4) | 2) {
    cumulative_[symbols] = kFrequencyTotal;
    for (unsigned s = 0; s < symbols; ++s) {
      frequency_[s] = kFrequencyTotal / symbols + (s < kFrequencyTotal % symbols ? 1 : 0);
    }
    refresh();
  }

  // Whether every refresh found the frequencies adding up to the total.
  bool balanced() const { return balanced_; }

  // The symbol whose interval holds `target` (< kFrequencyTotal), counted as decoded.
  Interval decode(std::uint32_t target) {
    // cumulative_[0] is 0 and the counts strictly increase: one symbol holds the target,
    // at or after the one that holds the start of the target's bucket.
    unsigned symbol = bucket_start_[target >> kBucketShift];
    while (cumulative_[symbol + 1] <= target) ++symbol;
    const Interval interval{symbol, cumulative_[symbol],
                            cumulative_[symbol + 1] - cumulative_[symbol]};
    if (until_refresh_ == 0) refresh();
    --until_refresh_;
    frequency_[symbol] += increment_;
    return interval;
  }

 private:
  void refresh() {
    if (with_larger_increment_ != 0) {  // the last symbols of a period add one more
      until_refresh_ = with_larger_increment_;
      with_larger_increment_ = 0;
      ++increment_;
      return;
    }
    rescale_interval_ = std::min(rescale_interval_ * 2, kLongestRescaleInterval);
    std::uint32_t cumulative = kFrequencyTotal;
    std::uint32_t unshared = kFrequencyTotal;
    for (std::size_t s = frequency_.size(); s-- > 0;) {
      cumulative -= frequency_[s];
      cumulative_[s] = cumulative;
      frequency_[s] = (frequency_[s] >> 1) | 1;
      unshared -= frequency_[s];
    }
    // The frequencies always add up to the total again here (the increments of a period
    // share out exactly what halving left over), so the counts start at 0, as fpzip's
    // lookup table needs; checked all the same, since the walk's argument rests on it.
    balanced_ = balanced_ && cumulative == 0;
    for (unsigned bucket = 0, symbol = 0; bucket < kBuckets; ++bucket) {
      while (cumulative_[symbol + 1] <= bucket << kBucketShift) ++symbol;
      bucket_start_[bucket] = symbol;
    }
    increment_ = unshared / rescale_interval_;
    with_larger_increment_ = unshared % rescale_interval_;
    until_refresh_ = rescale_interval_ - with_larger_increment_;
  }

  // Where to start looking for a target: buckets of 2^9 cumulative counts.
  static constexpr unsigned kBucketShift = 9;
  static constexpr unsigned kBuckets = kFrequencyTotal >> kBucketShift;

  std::vector<std::uint32_t> frequency_;
  std::array<unsigned, kBuckets> bucket_start_{};
  std::vector<std::uint32_t> cumulative_;
  std::uint32_t rescale_interval_;
  std::uint32_t increment_ = 0;
  std::uint32_t with_larger_increment_ = 0;
  std::uint32_t until_refresh_ = 0;
  bool balanced_ = true;
};

// fpzip's range decoder state (low end, length of the interval, incoming code) over a
// stream whose end it knows; fpzip's own reader reads one byte after another unchecked.
class RangeWalk {
 public:
  RangeWalk(std::span<const std::byte> stream, std::string_view what)
      : stream_(stream), what_(what) {
    fetch(4);
  }

  std::size_t bytes_read() const { return next_; }

  // A symbol of `model`. fpzip looks the target up in tables sized for targets below the
  // model's total; a stream that leads elsewhere is not one fpzip wrote.
  unsigned symbol(AdaptiveFrequencies& model) {
    range_ >>= kFrequencyBits;
    const std::uint32_t target = (code_ - low_) / nonzero_range();
    if (target >= kFrequencyTotal) {
      throw make_error(ErrorCode::kCorrupt,
                       "{}: fpzip stream is not one fpzip wrote (byte {} of {} leads outside the "
                       "decoder's frequency tables)",
                       what_, next_, stream_.size());
    }
    const AdaptiveFrequencies::Interval interval = model.decode(target);
    if (!model.balanced()) {
      throw make_error(ErrorCode::kInternal,
                       "{}: fpzip's frequency model lost its balance at stream byte {}", what_,
                       next_);
    }
    low_ += range_ * interval.start;
    range_ *= interval.size;
    renormalize();
    return interval.symbol;
  }

  // `bits` (at most 16) bits stored without a model; their value does not matter here.
  void skip_bits(unsigned bits) {
    range_ >>= bits;
    low_ += range_ * ((code_ - low_) / nonzero_range());
    renormalize();
  }

 private:
  // The decoder keeps the range at 2^16 or more between symbols, so this never throws; it
  // keeps the walk itself from dividing by zero should that reasoning ever be wrong.
  std::uint32_t nonzero_range() const {
    if (range_ == 0) {
      throw make_error(ErrorCode::kCorrupt, "{}: fpzip stream empties the decoder's range at byte {}",
                       what_, next_);
    }
    return range_;
  }

  void renormalize() {
    while (((low_ ^ (low_ + range_)) >> 24) == 0) {  // top byte settled
      fetch(1);
      range_ <<= 8;
    }
    if ((range_ >> 16) == 0) {  // range too small to go on without a carry
      fetch(2);
      range_ = 0u - low_;
    }
  }

  void fetch(unsigned count) {
    for (unsigned i = 0; i < count; ++i) {
      if (next_ == stream_.size()) {
        throw make_error(ErrorCode::kCorrupt,
                         "{}: fpzip stream of {} bytes ends before the brick is decoded", what_,
                         stream_.size());
      }
      code_ = (code_ << 8) | std::to_integer<std::uint32_t>(stream_[next_++]);
      low_ <<= 8;
    }
  }

  std::span<const std::byte> stream_;
  std::string_view what_;
  std::size_t next_ = 0;
  std::uint32_t low_ = 0;
  std::uint32_t range_ = ~std::uint32_t{0};
  std::uint32_t code_ = 0;
};

// fpzip's predictive coder at full precision for `kBits`-bit samples: per sample a class
// s of 2 * kBits + 1 from the model (kBits: predicted exactly), then for s != kBits a
// residual of k = |s - kBits| - 1 raw bits, read in pieces of 16 while more than 16 are
// left (at most kBits / 16 - 1 such pieces), then the rest.
template <unsigned kBits>
void walk_samples(RangeWalk& walk, std::size_t samples) {
  AdaptiveFrequencies classes(2 * kBits + 1);
  for (std::size_t i = 0; i < samples; ++i) {
    const unsigned s = walk.symbol(classes);
    if (s == kBits) continue;
    unsigned k = s > kBits ? s - kBits - 1 : kBits - 1 - s;
    for (unsigned piece = 1; piece < kBits / 16; ++piece) {
      if (k > 16) {
        walk.skip_bits(16);
        k -= 16;
      }
    }
    walk.skip_bits(k);
  }
}

}  // namespace

std::size_t check_fpzip_stream(std::span<const std::byte> stream, DType dtype, BrickDims dims,
                               std::string_view what) {
  for (const std::size_t side : dims) {
    if (side == 0 || side > kMaxFpzipBrickSide) {
      throw make_error(ErrorCode::kCorrupt,
                       "{}: a {}x{}x{} brick cannot be an fpzip chunk (sides 1 to {})", what,
                       dims[0], dims[1], dims[2], kMaxFpzipBrickSide);
    }
  }
  const std::size_t samples = dims[0] * dims[1] * dims[2];
  RangeWalk walk(stream, what);
  if (dtype == DType::kFloat64) {
    walk_samples<64>(walk, samples);
  } else {
    walk_samples<32>(walk, samples);
  }
  return walk.bytes_read();
}

}  // namespace strielad
