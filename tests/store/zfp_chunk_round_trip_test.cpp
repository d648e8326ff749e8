// SPDX-License-Identifier: Apache-2.0
// zfp chunks (formats/store.md, "zfp chunks (version 6)") keep every valid sample within
// the bound for float32 and float64, with missing samples, subnormals and 1e30 values in
// the brick; missing samples decode as NaN and valid ones never do; a brick zfp cannot
// code within the bound (an infinity, an accuracy looser than the bound) is refused so the
// writer keeps it lossless; damaged, truncated and crafted chunks are rejected as corrupt
// with the node's name, never read past.
#define XXH_INLINE_ALL
#include <xxhash.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "store/zfp_chunk.h"
#include "support/brick_samples.h"
#include "support/expect_error.h"
#include "support/guarded_bytes.h"

namespace strielad {
namespace {

using testing::bytes_of;
using testing::count;
using testing::dtype_of;
using testing::expect_error;

constexpr BrickDims kBrick{24, 24, 24};

// A temperature-like field in kelvin with a hole of missing samples (terrain).
template <typename T>
std::vector<T> field_with_hole(BrickDims d) {
  std::vector<T> v(count(d));
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double x = double(i % d[0]), y = double((i / d[0]) % d[1]), z = double(i / (d[0] * d[1]));
    v[i] = static_cast<T>(280.0 - 0.6 * z + 3.0 * std::sin(0.3 * x) * std::cos(0.2 * y));
    if (z < 3 && x + y < 10) v[i] = std::numeric_limits<T>::quiet_NaN();
  }
  return v;
}

// Decodes `chunk` and checks the bound on every valid sample and NaN on every missing one.
template <typename T>
void expect_within(const std::vector<std::byte>& chunk, const std::vector<T>& original,
                   BrickDims d, double bound) {
  std::vector<T> decoded(original.size());
  decompress_brick_zfp(chunk, dtype_of(T{}), d, std::as_writable_bytes(std::span(decoded)), "node 7");
  for (std::size_t i = 0; i < original.size(); ++i) {
    if (std::isnan(original[i])) {
      ASSERT_TRUE(std::isnan(decoded[i])) << "sample " << i << " was missing";
      continue;
    }
    ASSERT_TRUE(std::isfinite(decoded[i])) << "sample " << i;
    ASSERT_LE(std::abs(double(decoded[i]) - double(original[i])), bound)
        << "sample " << i << ": " << original[i] << " decoded as " << decoded[i];
  }
}

template <typename T>
void bound_holds_and_missing_stays_missing() {
  const std::vector<T> v = field_with_hole<T>(kBrick);
  for (const double bound : {1.0, 0.1, 0.01, 1e-4}) {
    const ZfpCodingResult r = compress_brick_zfp(bytes_of(v), dtype_of(T{}), kBrick, bound, bound);
    ASSERT_EQ(r.outcome, ZfpOutcome::kCoded) << "bound " << bound;
    EXPECT_LE(r.max_error, bound);
    EXPECT_LT(r.chunk.size(), v.size() * sizeof(T));
    expect_within(r.chunk, v, kBrick, bound);
  }
}

TEST(ZfpChunk, BoundHoldsAndMissingStaysMissingFloat32) { bound_holds_and_missing_stays_missing<float>(); }
TEST(ZfpChunk, BoundHoldsAndMissingStaysMissingFloat64) { bound_holds_and_missing_stays_missing<double>(); }

TEST(ZfpChunk, LooserToleranceMakesSmallerChunks) {
  const std::vector<float> v = field_with_hole<float>(kBrick);
  const auto fine = compress_brick_zfp(bytes_of(v), DType::kFloat32, kBrick, 0.001, 0.001);
  const auto coarse = compress_brick_zfp(bytes_of(v), DType::kFloat32, kBrick, 0.5, 0.5);
  ASSERT_EQ(fine.outcome, ZfpOutcome::kCoded);
  ASSERT_EQ(coarse.outcome, ZfpOutcome::kCoded);
  EXPECT_LT(coarse.chunk.size() * 2, fine.chunk.size());
  EXPECT_LT(coarse.chunk.size() * 8, v.size() * 4);  // a dense field at 0.5 K: > 8x
}

// Subnormals, 1e30 and tiny values in one brick: zfp's common block exponent loses the
// small ones next to 1e30, so such bricks must be refused, never stored beyond the bound.
template <typename T>
void extremes_never_break_the_bound() {
  using L = std::numeric_limits<T>;
  std::mt19937_64 rng(42);
  const T specials[] = {L::denorm_min(), -L::denorm_min(), L::min() / 3, T(0), -T(0),
                        static_cast<T>(1e30), static_cast<T>(-1e30), static_cast<T>(1e-30),
                        L::quiet_NaN()};
  int coded = 0, refused = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<T> v = field_with_hole<T>(BrickDims{9, 8, 7});
    for (T& s : v) {
      if (rng() % (trial < 10 ? 4 : 200) == 0) s = specials[rng() % std::size(specials)];
    }
    for (const double bound : {1e-3, 10.0}) {
      const auto r = compress_brick_zfp(bytes_of(v), dtype_of(T{}), BrickDims{9, 8, 7}, bound, bound);
      if (r.outcome == ZfpOutcome::kCoded) {
        ++coded;
        expect_within(r.chunk, v, BrickDims{9, 8, 7}, bound);
      } else {
        ++refused;
      }
    }
  }
  EXPECT_GT(refused, 0);  // bricks with 1e30 next to 280 K cannot keep 1e-3
  EXPECT_GT(coded, 0);
}

TEST(ZfpChunk, ExtremesNeverBreakTheBoundFloat32) { extremes_never_break_the_bound<float>(); }
TEST(ZfpChunk, ExtremesNeverBreakTheBoundFloat64) { extremes_never_break_the_bound<double>(); }

TEST(ZfpChunk, SubnormalOnlyBrickKeepsTheBound) {
  std::vector<float> v(count(BrickDims{8, 8, 8}));
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = std::numeric_limits<float>::denorm_min() * float(i % 13);
  const double bound = 1e-44;
  const auto r = compress_brick_zfp(bytes_of(v), DType::kFloat32, BrickDims{8, 8, 8}, bound, bound);
  if (r.outcome == ZfpOutcome::kCoded) expect_within(r.chunk, v, BrickDims{8, 8, 8}, bound);
  const auto loose = compress_brick_zfp(bytes_of(v), DType::kFloat32, BrickDims{8, 8, 8}, 1e-30, 1e-30);
  ASSERT_EQ(loose.outcome, ZfpOutcome::kCoded);
  expect_within(loose.chunk, v, BrickDims{8, 8, 8}, 1e-30);
}

TEST(ZfpChunk, AccuracyLooserThanTheBoundIsRefused) {
  const std::vector<float> v = field_with_hole<float>(kBrick);
  const auto r = compress_brick_zfp(bytes_of(v), DType::kFloat32, kBrick, 0.01, 10.0);
  EXPECT_EQ(r.outcome, ZfpOutcome::kBoundExceeded);
  EXPECT_GT(r.max_error, 0.01);
  EXPECT_TRUE(r.chunk.empty());
}

TEST(ZfpChunk, InfinityIsRefused) {
  std::vector<double> v = field_with_hole<double>(BrickDims{5, 5, 5});
  v[60] = std::numeric_limits<double>::infinity();
  const auto r = compress_brick_zfp(bytes_of(v), DType::kFloat64, BrickDims{5, 5, 5}, 1.0, 1.0);
  EXPECT_EQ(r.outcome, ZfpOutcome::kBoundExceeded);
}

TEST(ZfpChunk, NoiseAtATinyBoundIsNotSmaller) {
  std::mt19937 rng(7);
  std::vector<float> v(count(kBrick));
  for (float& s : v) s = std::uniform_real_distribution<float>(-1e6f, 1e6f)(rng);
  const auto r = compress_brick_zfp(bytes_of(v), DType::kFloat32, kBrick, 1e-6, 1e-6);
  EXPECT_NE(r.outcome, ZfpOutcome::kCoded);
}

TEST(ZfpChunk, BadBoundIsAnInvalidArgument) {
  const std::vector<float> v(8, 1.f);
  for (const double bad : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    expect_error([&] { compress_brick_zfp(bytes_of(v), DType::kFloat32, BrickDims{2, 2, 2}, bad, 1.0); },
                 ErrorCode::kInvalidArgument, {"bound"});
  }
}

std::vector<std::byte> small_chunk() {
  const std::vector<float> v = field_with_hole<float>(BrickDims{6, 5, 4});
  auto r = compress_brick_zfp(bytes_of(v), DType::kFloat32, BrickDims{6, 5, 4}, 0.05, 0.05);
  EXPECT_EQ(r.outcome, ZfpOutcome::kCoded);
  return r.chunk;
}

TEST(ZfpChunk, EveryChangedByteIsCorrupt) {
  const std::vector<std::byte> chunk = small_chunk();
  std::vector<std::byte> out(6 * 5 * 4 * 4);
  for (std::size_t i = 0; i < chunk.size(); ++i) {
    std::vector<std::byte> bad = chunk;
    bad[i] ^= std::byte{0x41};
    expect_error([&] { decompress_brick_zfp(bad, DType::kFloat32, BrickDims{6, 5, 4}, out, "node 7"); },
                 ErrorCode::kCorrupt, {"node 7", "zfp"});
  }
}

TEST(ZfpChunk, EveryTruncationIsCorrupt) {
  const std::vector<std::byte> chunk = small_chunk();
  testing::GuardedBytes guarded(chunk.size());
  std::vector<std::byte> out(6 * 5 * 4 * 4);
  for (std::size_t n = 0; n < chunk.size(); ++n) {
    const auto cut = guarded.place(std::span(chunk).first(n));
    expect_error([&] { decompress_brick_zfp(cut, DType::kFloat32, BrickDims{6, 5, 4}, out, "node 7"); },
                 ErrorCode::kCorrupt, {"node 7"});
  }
}

TEST(ZfpChunk, ChunkOfAnotherShapeOrTypeIsCorrupt) {
  const std::vector<std::byte> chunk = small_chunk();
  std::vector<std::byte> out(6 * 5 * 4 * 8);
  expect_error([&] { decompress_brick_zfp(chunk, DType::kFloat32, BrickDims{5, 6, 4}, std::span(out).first(480), "node 7"); },
               ErrorCode::kCorrupt, {"node 7", "stream checksum"});
  expect_error([&] { decompress_brick_zfp(chunk, DType::kFloat64, BrickDims{6, 5, 4}, out, "node 7"); },
               ErrorCode::kCorrupt, {"node 7", "stream checksum"});
}

// An attacker recomputes the stream checksum: random runs, modes and streams must still be
// rejected (or decode to samples whose checksum then fails), never crash or read past.
TEST(ZfpChunk, CraftedChunksWithValidStreamChecksumAreRejected) {
  const std::vector<std::byte> chunk = small_chunk();
  testing::GuardedBytes guarded(1 << 16);
  std::vector<std::byte> out(6 * 5 * 4 * 4);
  std::mt19937_64 rng(3);
  const std::uint64_t seed = 6 | std::uint64_t{5} << 20 | std::uint64_t{4} << 40 | std::uint64_t{1} << 61;
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<std::byte> bad = chunk;
    if (trial % 3 == 2) bad.resize(17 + rng() % 600);
    for (int k = 0, n = 1 + int(rng() % 8); k < n; ++k) {
      bad[16 + rng() % (bad.size() - 16)] = static_cast<std::byte>(rng());
    }
    const std::uint64_t sum = XXH3_64bits_withSeed(bad.data() + 16, bad.size() - 16, seed);
    std::memcpy(bad.data() + 8, &sum, 8);
    const auto placed = guarded.place(bad);
    try {
      decompress_brick_zfp(placed, DType::kFloat32, BrickDims{6, 5, 4}, out, "node 7");
    } catch (const Error& e) {
      ASSERT_EQ(e.code(), ErrorCode::kCorrupt) << e.what();
    }
  }
}

// What zfp reads of a hostile stream stays within the buffer the reader gives it
// (formats/store.md, "What zfp sees"): streams of all ones, alternating bits and random
// words, checksums recomputed, make zfp read at most its per-block bound; the reader
// reports how far it read when that is not exactly the stream.
TEST(ZfpChunk, HostileStreamsAreReadWithinTheBlockBound) {
  const std::vector<std::byte> valid = small_chunk();  // 6x5x4 float32: 2x2x1 blocks
  const std::uint32_t runs_size = [&] {
    std::uint32_t r = 0;
    std::memcpy(&r, valid.data() + 28, 4);
    return r;
  }();
  const std::size_t bound_bytes = 4 * (9 + 32 * 129) / 8 + 8;
  const std::uint64_t seed = 6 | std::uint64_t{5} << 20 | std::uint64_t{4} << 40 | std::uint64_t{1} << 61;
  std::vector<std::byte> out(6 * 5 * 4 * 4);
  std::mt19937_64 rng(11);
  std::size_t largest = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const std::size_t words = 1 + rng() % 40;
    std::vector<std::byte> bad(valid.begin(), valid.begin() + 32 + runs_size);
    for (std::size_t w = 0; w < words; ++w) {
      const std::uint64_t word = trial % 3 == 0 ? ~std::uint64_t{0}
                                 : trial % 3 == 1 ? 0xAAAAAAAAAAAAAAAAull ^ (rng() & 0xff)
                                                  : rng();
      const auto* b = reinterpret_cast<const std::byte*>(&word);
      bad.insert(bad.end(), b, b + 8);
    }
    const std::uint64_t sum = XXH3_64bits_withSeed(bad.data() + 16, bad.size() - 16, seed);
    std::memcpy(bad.data() + 8, &sum, 8);
    try {
      decompress_brick_zfp(bad, DType::kFloat32, BrickDims{6, 5, 4}, out, "node 7");
    } catch (const Error& e) {
      ASSERT_EQ(e.code(), ErrorCode::kCorrupt) << e.what();
      const std::string m = e.what();
      const auto at = m.find("decodes from ");
      if (at == std::string::npos) continue;
      const std::size_t read = std::stoul(m.substr(at + 13));
      largest = std::max(largest, read);
      ASSERT_LE(read, bound_bytes) << m;
    }
  }
  EXPECT_GT(largest, 0u);
}

}  // namespace
}  // namespace strielad
