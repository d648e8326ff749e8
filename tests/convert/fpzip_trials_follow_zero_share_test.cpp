// SPDX-License-Identifier: Apache-2.0
// With fpzip on, a data brick's share of zero samples decides which coders it tries
// (build/brick_encoder.h): fpzip alone below kFpzipAloneBelowZeroShare when it halves the
// brick, the smaller of both up to kFpzipTriedBelowZeroShare, the Blosc chain alone from
// there. Every chunk decodes to the brick's samples bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "convert/brick_encoder.h"
#include "store/brick_codec.h"
#include "store/fpzip_chunk.h"

namespace strielad {
namespace {

constexpr std::size_t kSide = 17;
constexpr std::size_t kCount = kSide * kSide * kSide;

format::CodecSpec blosc_codec(bool fpzip) {
  format::CodecSpec c;  // zstd 1, byte shuffle, no predictor: the store's default chain
  c.fpzip = fpzip;
  return c;
}

std::span<const std::byte> bytes_of(const std::vector<float>& v) {
  return std::as_bytes(std::span(v));
}

// A smooth cloud-like field in which the first `zero_share` of the samples (in x-fastest
// order, so whole planes from the bottom) are exactly zero.
std::vector<float> smooth_brick(double zero_share) {
  std::vector<float> v(kCount);
  const auto zeros = static_cast<std::size_t>(std::lround(zero_share * kCount));
  for (std::size_t i = 0; i < kCount; ++i) {
    const double x = double(i % kSide), y = double(i / kSide % kSide), z = double(i / kSide / kSide);
    v[i] = i < zeros ? 0.0f
                     : static_cast<float>(1e-4 * (1.5 + std::sin(0.3 * x) * std::cos(0.2 * y) +
                                                  0.05 * z));
  }
  return v;
}

build::EncodedBrick encode(const std::vector<float>& v, const format::CodecSpec& codec) {
  const build::PlaneBlock<float> block{v.data(), {kSide, kSide, kSide}, 0, kSide};
  const IndexBox box{{0, 0, 0}, {kSide - 1, kSide - 1, kSide - 1}};
  return build::encode_brick(block, box, &box, {}, codec);
}

std::vector<float> decode(const build::EncodedBrick& b, const format::CodecSpec& codec) {
  std::vector<float> out(kCount);
  const BrickDims dims{kSide, kSide, kSide};
  const auto out_bytes = std::as_writable_bytes(std::span(out));
  if (b.entry.coding == format::ChunkCoding::kFpzip) {
    decompress_brick_fpzip(b.chunk, DType::kFloat32, dims, out_bytes, "test brick");
  } else {
    decompress_brick(b.chunk, DType::kFloat32, dims, codec, out_bytes, "test brick");
  }
  return out;
}

std::size_t blosc_size(const std::vector<float>& v) {
  return compress_brick(bytes_of(v), DType::kFloat32, BrickDims{kSide, kSide, kSide},
                        blosc_codec(false))
      .size();
}

std::size_t fpzip_size(const std::vector<float>& v) {
  const auto f = compress_brick_fpzip(bytes_of(v), DType::kFloat32, BrickDims{kSide, kSide, kSide});
  return f ? f->size() : SIZE_MAX;
}

void expect_decodes_exactly(const std::vector<float>& v, const build::EncodedBrick& b) {
  const std::vector<float> back = decode(b, blosc_codec(true));
  EXPECT_EQ(std::memcmp(back.data(), v.data(), v.size() * sizeof(float)), 0);
  EXPECT_EQ(b.entry.chunk_size, b.chunk.size());
}

TEST(FpzipTrialsFollowZeroShare, ABrickWithFewZerosIsFpzipAloneWhenItHalvesTheBrick) {
  const auto v = smooth_brick(0.1);
  ASSERT_LT(0.1, build::kFpzipAloneBelowZeroShare);
  const build::EncodedBrick b = encode(v, blosc_codec(true));
  ASSERT_EQ(b.entry.kind, format::BrickKind::kData);
  EXPECT_EQ(b.entry.coding, format::ChunkCoding::kFpzip);
  EXPECT_EQ(b.chunk.size(), fpzip_size(v));
  EXPECT_LE(2 * b.chunk.size(), kCount * sizeof(float));
  expect_decodes_exactly(v, b);
}

TEST(FpzipTrialsFollowZeroShare, ABrickWithFewZerosThatFpzipCannotHalveKeepsTheSmallerChunk) {
  // Random mantissas in a narrow exponent band: neither coder halves it.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> noise(1.0f, 2.0f);
  std::vector<float> v(kCount);
  for (float& x : v) x = noise(rng);
  const build::EncodedBrick b = encode(v, blosc_codec(true));
  ASSERT_GT(2 * fpzip_size(v), kCount * sizeof(float));
  EXPECT_EQ(b.chunk.size(), std::min(fpzip_size(v), blosc_size(v)));
  EXPECT_EQ(b.entry.coding, fpzip_size(v) < blosc_size(v) ? format::ChunkCoding::kFpzip
                                                           : format::ChunkCoding::kCodec);
  expect_decodes_exactly(v, b);
}

TEST(FpzipTrialsFollowZeroShare, BetweenTheSharesTheSmallerOfBothChunksIsKept) {
  for (const double share : {0.55, 0.65, 0.75}) {
    ASSERT_GE(share, build::kFpzipAloneBelowZeroShare);
    ASSERT_LT(share, build::kFpzipTriedBelowZeroShare);
    const auto v = smooth_brick(share);
    const build::EncodedBrick b = encode(v, blosc_codec(true));
    EXPECT_EQ(b.chunk.size(), std::min(fpzip_size(v), blosc_size(v))) << share;
    EXPECT_EQ(b.entry.coding, fpzip_size(v) < blosc_size(v) ? format::ChunkCoding::kFpzip
                                                             : format::ChunkCoding::kCodec)
        << share;
    expect_decodes_exactly(v, b);
  }
}

TEST(FpzipTrialsFollowZeroShare, AMostlyZeroBrickUsesTheBloscChainAloneEvenWhereFpzipWouldWin) {
  const auto v = smooth_brick(0.85);
  ASSERT_GE(0.85, build::kFpzipTriedBelowZeroShare);
  ASSERT_LT(fpzip_size(v), blosc_size(v)) << "the case must be one fpzip would win";
  const build::EncodedBrick b = encode(v, blosc_codec(true));
  EXPECT_EQ(b.entry.coding, format::ChunkCoding::kCodec);
  EXPECT_EQ(b.chunk.size(), blosc_size(v));
  expect_decodes_exactly(v, b);
}

TEST(FpzipTrialsFollowZeroShare, NegativeZerosCountAsZerosAndWithoutFpzipNothingChanges) {
  auto v = smooth_brick(0.85);
  for (std::size_t i = 0; i < kCount; i += 2) {
    if (v[i] == 0.0f) v[i] = -0.0f;
  }
  EXPECT_EQ(encode(v, blosc_codec(true)).entry.coding, format::ChunkCoding::kCodec);
  const auto few = smooth_brick(0.1);
  const build::EncodedBrick plain = encode(few, blosc_codec(false));
  EXPECT_EQ(plain.entry.coding, format::ChunkCoding::kCodec);
  EXPECT_EQ(plain.chunk.size(), blosc_size(few));
  expect_decodes_exactly(few, plain);
}

}  // namespace
}  // namespace strielad
