// SPDX-License-Identifier: Apache-2.0
// Crafted fpzip chunks, with every checksum recomputed as an attacker would, are rejected
// with strielad::Error before fpzip sees them, never crash the reader: the fuzzers'
// regression inputs, streams that send fpzip's decoder outside its frequency tables,
// valid streams cut at every byte or with any byte changed, random streams, streams of one
// brick filed under another shape or type, and bricks no fpzip chunk can have. Every
// chunk sits flush against an inaccessible page, so a read past it by (uninstrumented)
// libfpzip faults here.
#define XXH_INLINE_ALL
#include <xxhash.h>

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <vector>

#include "core/checksum.h"
#include "store/fpzip_chunk.h"
#include "store/fpzip_stream_check.h"
#include "support/brick_samples.h"
#include "support/expect_error.h"
#include "support/guarded_bytes.h"

namespace strielad {
namespace {

using testing::expect_error;
using testing::GuardedBytes;

// What a chunk writer computes (formats/store.md, "fpzip chunks").
std::uint64_t stream_checksum(std::span<const std::byte> stream, DType dtype, BrickDims dims) {
  const std::uint64_t seed = std::uint64_t{dims[0]} | std::uint64_t{dims[1]} << 20 |
                             std::uint64_t{dims[2]} << 40 |
                             std::uint64_t{dtype == DType::kFloat64 ? 1u : 0u} << 60;
  return XXH3_64bits_withSeed(stream.data(), stream.size(), seed);
}

// A chunk around `stream` whose checksums match, for the brick of `dims` and `dtype`.
std::vector<std::byte> forged_chunk(std::span<const std::byte> stream, DType dtype,
                                    BrickDims dims, std::uint64_t samples_sum = 0) {
  std::vector<std::byte> chunk(kFpzipChunkHeaderSize + stream.size());
  const std::uint64_t sums[2] = {samples_sum, stream_checksum(stream, dtype, dims)};
  std::memcpy(chunk.data(), sums, sizeof sums);
  if (!stream.empty()) std::memcpy(chunk.data() + kFpzipChunkHeaderSize, stream.data(), stream.size());
  return chunk;
}

std::vector<std::byte> hex_bytes(std::initializer_list<unsigned> values) {
  std::vector<std::byte> bytes;
  for (unsigned v : values) bytes.push_back(static_cast<std::byte>(v));
  return bytes;
}

std::size_t brick_bytes(DType dtype, BrickDims dims) {
  return dims[0] * dims[1] * dims[2] * dtype_size(dtype);
}

// Decodes `chunk`, placed flush against a guard page, as a brick of `dims` and `dtype`.
void decode_guarded(std::span<const std::byte> chunk, DType dtype, BrickDims dims,
                    std::vector<std::byte>& out) {
  static GuardedBytes guarded(std::size_t{1} << 20);
  out.assign(brick_bytes(dtype, dims), std::byte{0});
  decompress_brick_fpzip(guarded.place(chunk), dtype, dims, out, "hostile.bricks: node 7");
}

// Expects a kCorrupt naming the brick.
void expect_rejected(std::span<const std::byte> chunk, DType dtype, BrickDims dims) {
  std::vector<std::byte> out;
  expect_error([&] { decode_guarded(chunk, dtype, dims, out); }, ErrorCode::kCorrupt,
               {"hostile.bricks: node 7"});
}

// Decoding either fails with a strielad::Error or yields exactly `expected` (a change fpzip
// never reads, or a coincidence the samples checksum cannot tell).
void expect_rejected_or_equal(std::span<const std::byte> chunk, DType dtype, BrickDims dims,
                              std::span<const std::byte> expected) {
  std::vector<std::byte> out;
  try {
    decode_guarded(chunk, dtype, dims, out);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kCorrupt) << e.what();
    return;
  }
  EXPECT_TRUE(std::equal(out.begin(), out.end(), expected.begin(), expected.end()));
}

struct Brick {
  DType dtype;
  BrickDims dims;
};

// The decodings the brick-chunk fuzz target tries on each input.
const Brick kFuzzedBricks[] = {{DType::kFloat32, {5, 5, 5}},
                               {DType::kFloat32, {1, 3, 5}},
                               {DType::kFloat64, {1, 5, 5}}};

std::vector<std::byte> smooth_samples(DType dtype, BrickDims dims) {
  std::vector<std::byte> bytes(brick_bytes(dtype, dims));
  const std::size_t n = dims[0] * dims[1] * dims[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double v = 0.25 * double(i % dims[0]) + 0.5 * double(i / dims[0]) + 1e-3 * double(i % 7);
    if (dtype == DType::kFloat64) {
      std::memcpy(bytes.data() + 8 * i, &v, 8);
    } else {
      const float f = static_cast<float>(v);
      std::memcpy(bytes.data() + 4 * i, &f, 4);
    }
  }
  return bytes;
}

TEST(FpzipHostileChunksTest, FuzzerRegressionInputsAreRejectedForEveryFuzzedBrick) {
  const auto folder =
      std::filesystem::path(STRIELAD_SOURCE_DIR) / "tests/fuzz/regressions/brick_chunk_decoder";
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    const std::vector<char> raw{std::istreambuf_iterator<char>(in), {}};
    const std::span<const std::byte> chunk(reinterpret_cast<const std::byte*>(raw.data()), raw.size());
    ++files;
    for (const Brick& b : kFuzzedBricks) {
      SCOPED_TRACE(entry.path().filename().string());
      expect_rejected(chunk, b.dtype, b.dims);
    }
  }
  EXPECT_GT(files, 0u) << folder;
}

// Streams on which fpzip's decoder computes a cumulative frequency far beyond its model's
// total and indexes its tables with it (found by running libfpzip on random bytes: each
// faulted in every fresh process).
TEST(FpzipHostileChunksTest, StreamsLeadingOutsideFpzipsFrequencyTablesAreRejected) {
  const std::vector<std::byte> streams[] = {
      hex_bytes({0xff, 0xff, 0xff, 0xff}),
      hex_bytes({0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff}),
      hex_bytes({0xd7, 0x54, 0xe7, 0xb9, 0xc8, 0x57, 0x1e, 0x6d, 0xd7, 0xe3, 0x35, 0x28, 0x7a,
                 0x26, 0xff, 0x26, 0x00, 0x41, 0xb0, 0x1f, 0x00}),
      hex_bytes({0xff, 0x47, 0x4c, 0xff, 0xe9, 0x42, 0xa4, 0xc7, 0xa1, 0xe9, 0xa1, 0xfa, 0x54,
                 0xe8, 0xd5, 0xff, 0x8c, 0x44, 0x58, 0x28, 0xed, 0xb9, 0xff, 0xb5, 0xed, 0xff,
                 0x85}),
  };
  for (const auto& stream : streams) {
    for (const Brick& b : kFuzzedBricks) {
      const auto chunk = forged_chunk(stream, b.dtype, b.dims);
      EXPECT_THROW(check_fpzip_stream(stream, b.dtype, b.dims, "x"), Error);
      expect_rejected(chunk, b.dtype, b.dims);
    }
  }
}

TEST(FpzipHostileChunksTest, ChunksWithNoOrFewStreamBytesAreRejected) {
  for (std::size_t n = 0; n < 4; ++n) {
    const std::vector<std::byte> stream(n, std::byte{0x5a});
    for (const Brick& b : kFuzzedBricks) expect_rejected(forged_chunk(stream, b.dtype, b.dims), b.dtype, b.dims);
  }
  const std::vector<std::byte> header_only(kFpzipChunkHeaderSize);
  expect_rejected(header_only, DType::kFloat32, {5, 5, 5});
  expect_rejected({}, DType::kFloat32, {5, 5, 5});
}

TEST(FpzipHostileChunksTest, ValidStreamsCutAtEveryByteAreRejected) {
  for (const Brick& b : kFuzzedBricks) {
    const auto samples = smooth_samples(b.dtype, b.dims);
    const auto chunk = compress_brick_fpzip(samples, b.dtype, b.dims);
    ASSERT_TRUE(chunk);
    const std::span<const std::byte> stream = std::span(*chunk).subspan(kFpzipChunkHeaderSize);
    const std::size_t read = check_fpzip_stream(stream, b.dtype, b.dims, "x");
    for (std::size_t n = 0; n < stream.size(); ++n) {
      const std::span<const std::byte> cut = stream.first(n);
      if (n < read) {
        EXPECT_THROW(check_fpzip_stream(cut, b.dtype, b.dims, "x"), Error);
      }
      expect_rejected_or_equal(forged_chunk(cut, b.dtype, b.dims, checksum64(samples)), b.dtype,
                               b.dims, samples);
    }
  }
}

TEST(FpzipHostileChunksTest, ValidStreamsWithAnyByteChangedAreRejectedOrDecodeTheSamples) {
  for (const Brick& b : kFuzzedBricks) {
    const auto samples = smooth_samples(b.dtype, b.dims);
    const auto chunk = compress_brick_fpzip(samples, b.dtype, b.dims);
    ASSERT_TRUE(chunk);
    std::vector<std::byte> stream(chunk->begin() + kFpzipChunkHeaderSize, chunk->end());
    for (std::size_t i = 0; i < stream.size(); ++i) {
      for (const unsigned change : {0x01u, 0x80u, 0xffu}) {
        stream[i] ^= std::byte(change);
        expect_rejected_or_equal(forged_chunk(stream, b.dtype, b.dims, checksum64(samples)),
                                 b.dtype, b.dims, samples);
        stream[i] ^= std::byte(change);
      }
    }
  }
}

TEST(FpzipHostileChunksTest, RandomStreamsAreRejected) {
  std::mt19937_64 rng(28);
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<std::byte> stream(rng() % 96);
    const bool saturated = trial % 3 == 0;  // many 0xff bytes push the decoder's code high
    for (std::byte& x : stream) x = std::byte(saturated && rng() % 3 == 0 ? 0xff : rng() & 0xff);
    const Brick& b = kFuzzedBricks[trial % std::size(kFuzzedBricks)];
    const std::vector<std::byte> zeros(brick_bytes(b.dtype, b.dims));
    expect_rejected_or_equal(forged_chunk(stream, b.dtype, b.dims), b.dtype, b.dims, zeros);
  }
}

TEST(FpzipHostileChunksTest, StreamsFiledUnderAnotherShapeOrTypeAreRejected) {
  const Brick written{DType::kFloat32, {5, 5, 5}};
  const auto samples = smooth_samples(written.dtype, written.dims);
  const auto chunk = compress_brick_fpzip(samples, written.dtype, written.dims);
  ASSERT_TRUE(chunk);
  const std::span<const std::byte> stream = std::span(*chunk).subspan(kFpzipChunkHeaderSize);
  const Brick claimed[] = {{DType::kFloat32, {25, 25, 25}}, {DType::kFloat32, {64, 64, 64}},
                           {DType::kFloat64, {5, 5, 5}},    {DType::kFloat32, {5, 5, 6}},
                           {DType::kFloat32, {1, 1, 1}},    {DType::kFloat64, {1, 1, 2}}};
  for (const Brick& b : claimed) {
    const std::vector<std::byte> zeros(brick_bytes(b.dtype, b.dims));
    expect_rejected_or_equal(forged_chunk(stream, b.dtype, b.dims, checksum64(samples)), b.dtype,
                             b.dims, zeros);
  }
  EXPECT_THROW(check_fpzip_stream(stream, DType::kFloat32, {25, 25, 25}, "x"), Error);
}

TEST(FpzipHostileChunksTest, BricksNoFpzipChunkCanHaveAreRejectedBeforeFpzip) {
  const auto stream = hex_bytes({0x12, 0x34, 0x56, 0x78, 0x9a, 0xbc});
  const BrickDims impossible[] = {{0, 5, 5}, {5, 0, 5}, {5, 5, 0}, {kMaxFpzipBrickSide + 1, 1, 1},
                                  {1, kMaxFpzipBrickSide + 1, 1}, {1, 1, kMaxFpzipBrickSide + 1}};
  for (const BrickDims d : impossible) {
    expect_error([&] { check_fpzip_stream(stream, DType::kFloat32, d, "node 9"); },
                 ErrorCode::kCorrupt, {"node 9", "cannot be an fpzip chunk"});
    expect_rejected(forged_chunk(stream, DType::kFloat32, d), DType::kFloat32, d);
  }
  const std::vector<std::byte> samples(brick_bytes(DType::kFloat32, {kMaxFpzipBrickSide + 1, 1, 1}));
  EXPECT_FALSE(compress_brick_fpzip(samples, DType::kFloat32, {kMaxFpzipBrickSide + 1, 1, 1}));
}

TEST(FpzipHostileChunksTest, TheWalkReadsExactlyTheBytesFpzipReadsOnValidStreams) {
  for (const Brick& b : kFuzzedBricks) {
    const auto samples = smooth_samples(b.dtype, b.dims);
    const auto chunk = compress_brick_fpzip(samples, b.dtype, b.dims);
    ASSERT_TRUE(chunk);
    const std::span<const std::byte> stream = std::span(*chunk).subspan(kFpzipChunkHeaderSize);
    EXPECT_LE(check_fpzip_stream(stream, b.dtype, b.dims, "x"), stream.size());
    std::vector<std::byte> out;
    decode_guarded(*chunk, b.dtype, b.dims, out);
    EXPECT_EQ(out, samples);
  }
}

}  // namespace
}  // namespace strielad
