// SPDX-License-Identifier: Apache-2.0
// fpzip chunks (formats/store.md, "fpzip chunks") round-trip bit for bit for float32 and
// float64 whatever the samples hold (NaN payloads, infinities, subnormals, signed zeros,
// random bits) and whatever the brick's shape; they are smaller than the raw samples on a
// smooth field; every damaged, truncated or mismatched chunk is rejected with the node's
// name before or after fpzip, never read past.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "core/checksum.h"
#include "store/fpzip_chunk.h"
#include "support/brick_samples.h"
#include "support/expect_error.h"

namespace strielad {
namespace {

using testing::expect_error;

using testing::Bits;
using testing::bytes_of;
using testing::count;
using testing::dtype_of;

template <typename T>
std::vector<T> smooth_samples(BrickDims d) {
  std::vector<T> v(count(d));
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double x = double(i % d[0]), y = double((i / d[0]) % d[1]), z = double(i / (d[0] * d[1]));
    v[i] = static_cast<T>(1e-4 * std::exp(-0.02 * ((x - 9) * (x - 9) + (y - 7) * (y - 7))) *
                          (1.0 + 0.1 * z));
  }
  return v;
}

// A smooth field with every awkward bit pattern mixed in.
template <typename T>
std::vector<T> awkward_samples(BrickDims d, std::uint32_t seed) {
  using L = std::numeric_limits<T>;
  const T specials[] = {L::quiet_NaN(), -L::quiet_NaN(),
                        std::bit_cast<T>(static_cast<Bits<T>>(std::bit_cast<Bits<T>>(L::quiet_NaN()) | 0x2a)),
                        L::signaling_NaN(), L::infinity(), -L::infinity(), L::denorm_min(),
                        -L::denorm_min(), L::min() / 3, T(0), -T(0), L::max(), L::lowest(),
                        static_cast<T>(1e-30), static_cast<T>(1e30)};
  std::mt19937_64 rng(seed);
  std::vector<T> v = smooth_samples<T>(d);
  for (T& s : v) {
    switch (rng() % 6) {
      case 0: s = specials[rng() % std::size(specials)]; break;
      case 1: s = std::bit_cast<T>(static_cast<Bits<T>>(rng())); break;
      default: break;
    }
  }
  return v;
}

template <typename T>
void expect_round_trip(const std::vector<T>& samples, BrickDims d) {
  const auto chunk = compress_brick_fpzip(bytes_of(samples), dtype_of(T{}), d);
  if (!chunk) return;  // did not fit into the raw size: the writer keeps the other chunk
  std::vector<std::byte> back(samples.size() * sizeof(T));
  decompress_brick_fpzip(*chunk, dtype_of(T{}), d, back, "test");
  EXPECT_EQ(std::memcmp(back.data(), samples.data(), back.size()), 0)
      << "dims " << d[0] << "x" << d[1] << "x" << d[2] << " bytes " << sizeof(T);
}

const BrickDims kShapes[] = {{25, 25, 25}, {1, 1, 1}, {1, 9, 4}, {7, 1, 3}, {5, 6, 1}, {13, 8, 25}};

TEST(FpzipChunkTest, AwkwardAndSmoothSamplesRoundTripBitForBitInEveryShape) {
  std::uint32_t seed = 1;
  for (const BrickDims d : kShapes) {
    expect_round_trip(awkward_samples<float>(d, seed), d);
    expect_round_trip(awkward_samples<double>(d, seed), d);
    expect_round_trip(smooth_samples<float>(d), d);
    expect_round_trip(smooth_samples<double>(d), d);
    ++seed;
  }
}

TEST(FpzipChunkTest, ASmoothFieldCodesSmallerThanItsSamplesAndRandomBitsDoNot) {
  const BrickDims d{25, 25, 25};
  const auto smooth = smooth_samples<float>(d);
  const auto chunk = compress_brick_fpzip(bytes_of(smooth), DType::kFloat32, d);
  ASSERT_TRUE(chunk.has_value());
  EXPECT_LT(chunk->size(), smooth.size() * 4 * 3 / 4);
  std::mt19937 rng(7);
  std::vector<std::uint32_t> noise(count(d));
  for (auto& n : noise) n = rng();
  const auto random = compress_brick_fpzip(bytes_of(noise), DType::kFloat32, d);
  // Incompressible: no chunk, or one no smaller than the samples; either way a writer
  // comparing sizes keeps the codec chain's chunk.
  if (random) {
    EXPECT_GE(random->size(), noise.size() * 4 * 9 / 10);
  }
  // The header holds the XXH3 of the samples, little-endian.
  std::uint64_t stored = 0;
  for (int i = 0; i < 8; ++i) stored |= std::to_integer<std::uint64_t>((*chunk)[i]) << (8 * i);
  EXPECT_EQ(stored, checksum64(bytes_of(smooth)));
}

TEST(FpzipChunkTest, EveryFlippedByteAndEveryTruncationIsRejected) {
  const BrickDims d{9, 8, 7};
  const auto samples = smooth_samples<float>(d);
  const auto chunk = compress_brick_fpzip(bytes_of(samples), DType::kFloat32, d);
  ASSERT_TRUE(chunk.has_value());
  std::vector<std::byte> out(samples.size() * 4);
  const auto expect_rejected = [&](std::span<const std::byte> bad) {
    expect_error([&] { decompress_brick_fpzip(bad, DType::kFloat32, d, out, "f: node 3"); },
                 ErrorCode::kCorrupt, {"f: node 3", "fpzip chunk"});
  };
  for (std::size_t i = 0; i < chunk->size(); ++i) {
    auto bad = *chunk;
    bad[i] ^= std::byte{0x10};
    expect_rejected(bad);
  }
  for (std::size_t n = 0; n < chunk->size(); ++n) expect_rejected({chunk->data(), n});
}

TEST(FpzipChunkTest, AChunkReadAsAnotherShapeOrTypeIsRejected) {
  const BrickDims d{9, 8, 7};
  const auto samples = smooth_samples<float>(d);
  const auto chunk = compress_brick_fpzip(bytes_of(samples), DType::kFloat32, d);
  ASSERT_TRUE(chunk.has_value());
  // The stream checksum is seeded with the shape and type, so a sound stream filed under
  // another shape (even of the same sample count) or type is named as such. (A crafted
  // chunk recomputes it; the stream check stops that one: fpzip_hostile_chunks_test.)
  std::vector<std::byte> out(samples.size() * 4);
  expect_error([&] { decompress_brick_fpzip(*chunk, DType::kFloat32, {7, 8, 9}, out, "f"); },
               ErrorCode::kCorrupt, {"f: fpzip chunk's stream checksum", "not a 7x8x9 brick of float32"});
  std::vector<std::byte> wide(samples.size() * 8);
  expect_error([&] { decompress_brick_fpzip(*chunk, DType::kFloat64, d, wide, "f"); },
               ErrorCode::kCorrupt, {"f: fpzip chunk's stream checksum", "float64"});
  // Samples that differ from what was written (another fpzip build's arithmetic, here a
  // header whose samples checksum was altered) are caught after decoding.
  auto other = *chunk;
  other[0] ^= std::byte{1};
  expect_error([&] { decompress_brick_fpzip(other, DType::kFloat32, d, out, "f"); },
               ErrorCode::kCorrupt, {"f: fpzip chunk decodes to other samples"});
  // An output of the wrong size is the caller's bug.
  std::vector<std::byte> small(16);
  expect_error([&] { decompress_brick_fpzip(*chunk, DType::kFloat32, d, small, "f"); },
               ErrorCode::kInternal, {"decompress_brick_fpzip"});
}

}  // namespace
}  // namespace strielad
