// SPDX-License-Identifier: Apache-2.0
// Chunks round-trip bit for bit with either predictor, for float32 and float64, whatever
// the samples hold (NaN payloads, fill values, subnormals, infinities, signed zeros,
// constants, random bits) and whatever the brick's shape (one sample thick along any
// axis included); the lorenzo3 residual is the one formats/store.md defines; a damaged
// chunk is still reported.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "store/brick_codec.h"
#include "store/lorenzo_predictor.h"
#include "support/brick_samples.h"
#include "support/expect_error.h"

namespace strielad {
namespace {

using testing::expect_error;

using testing::Bits;
using testing::bytes_of;
using testing::count;
using testing::dtype_of;

// Samples of every awkward kind, mixed with a smooth field so the predictor has work.
template <typename T>
std::vector<T> awkward_samples(BrickDims d, std::uint32_t seed) {
  using L = std::numeric_limits<T>;
  std::mt19937_64 rng(seed);
  const T specials[] = {
      L::quiet_NaN(),
      -L::quiet_NaN(),
      std::bit_cast<T>(static_cast<Bits<T>>(std::bit_cast<Bits<T>>(L::quiet_NaN()) | 0x2a)),
      L::signaling_NaN(),
      L::infinity(),
      -L::infinity(),
      L::denorm_min(),
      -L::denorm_min(),
      L::min() / 3,
      T(0),
      -T(0),
      L::max(),
      L::lowest(),
      static_cast<T>(9.969209968386869e36),  // netCDF default float fill
      static_cast<T>(-9e33),
  };
  std::vector<T> v(count(d));
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::size_t x = i % d[0], y = (i / d[0]) % d[1], z = i / (d[0] * d[1]);
    switch (rng() % 5) {
      case 0: v[i] = specials[rng() % std::size(specials)]; break;
      case 1: v[i] = std::bit_cast<T>(static_cast<Bits<T>>(rng())); break;
      default: v[i] = static_cast<T>(280.0 + 0.3 * double(x) - 0.2 * double(y) + std::sin(0.1 * double(z)));
    }
  }
  return v;
}

template <typename T>
std::vector<T> smooth_samples(BrickDims d) {
  std::vector<T> v(count(d));
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double x = double(i % d[0]), y = double((i / d[0]) % d[1]), z = double(i / (d[0] * d[1]));
    v[i] = static_cast<T>(250.0 + 0.5 * z + 0.01 * x * y + std::sin(0.3 * x) * std::cos(0.2 * y));
  }
  return v;
}

template <typename T>
void expect_round_trip(const std::vector<T>& samples, BrickDims d, const format::CodecSpec& codec) {
  const auto chunk = compress_brick(bytes_of(samples), dtype_of(T{}), d, codec);
  std::vector<std::byte> back(samples.size() * sizeof(T));
  decompress_brick(chunk, dtype_of(T{}), d, codec, back, "test");
  EXPECT_EQ(std::memcmp(back.data(), samples.data(), back.size()), 0)
      << "dims " << d[0] << "x" << d[1] << "x" << d[2] << " codec " << codec.name << " "
      << codec.shuffle << " predictor " << codec.predictor << " bytes " << sizeof(T);
}

const BrickDims kShapes[] = {{25, 25, 25}, {7, 5, 3},  {1, 25, 25}, {25, 1, 25}, {25, 25, 1},
                             {1, 1, 25},   {1, 25, 1}, {25, 1, 1},  {1, 1, 1},   {2, 1, 3},
                             {13, 2, 2}};

template <typename T>
void round_trip_everything() {
  std::uint32_t seed = 1;
  for (const char* predictor : {"none", "lorenzo3"}) {
    for (const BrickDims& d : kShapes) {
      for (const char* name : {"zstd", "lz4", "blosclz"}) {
        for (const char* shuffle : {"none", "byte", "bit"}) {
          const format::CodecSpec codec{name, 1, shuffle, predictor};
          expect_round_trip(awkward_samples<T>(d, seed++), d, codec);
          expect_round_trip(smooth_samples<T>(d), d, codec);
          expect_round_trip(std::vector<T>(count(d), static_cast<T>(-1.5)), d, codec);
          expect_round_trip(std::vector<T>(count(d), std::numeric_limits<T>::quiet_NaN()), d,
                            codec);
        }
      }
    }
  }
}

TEST(BrickCodecPredictorTest, Float32RoundTripsBitExactWithEitherPredictor) {
  round_trip_everything<float>();
}

TEST(BrickCodecPredictorTest, Float64RoundTripsBitExactWithEitherPredictor) {
  round_trip_everything<double>();
}

// The residual is the formula of formats/store.md, computed here the slow way.
template <typename T>
void expect_spec_residual(BrickDims d, std::uint32_t seed) {
  using U = Bits<T>;
  const auto samples = awkward_samples<T>(d, seed);
  std::vector<U> u(samples.size());
  std::memcpy(u.data(), samples.data(), samples.size() * sizeof(T));
  const auto at = [&](std::ptrdiff_t x, std::ptrdiff_t y, std::ptrdiff_t z) -> U {
    if (x < 0 || y < 0 || z < 0) return 0;
    return u[(std::size_t(z) * d[1] + std::size_t(y)) * d[0] + std::size_t(x)];
  };
  std::vector<U> residual(u.size());
  lorenzo3_encode(reinterpret_cast<const std::byte*>(u.data()),
                  reinterpret_cast<std::byte*>(residual.data()), d, sizeof(U));
  for (std::size_t z = 0; z < d[2]; ++z)
    for (std::size_t y = 0; y < d[1]; ++y)
      for (std::size_t x = 0; x < d[0]; ++x) {
        U want = 0;
        for (int c = 0; c < 2; ++c)
          for (int b = 0; b < 2; ++b)
            for (int a = 0; a < 2; ++a) {
              const U term = at(std::ptrdiff_t(x) - a, std::ptrdiff_t(y) - b, std::ptrdiff_t(z) - c);
              want = ((a + b + c) % 2) ? U(want - term) : U(want + term);
            }
        const U zigzag = U(want << 1) ^ U(U{0} - (want >> (sizeof(U) * 8 - 1)));
        ASSERT_EQ(residual[(z * d[1] + y) * d[0] + x], zigzag)
            << "sample " << x << "," << y << "," << z << " of " << d[0] << "x" << d[1] << "x" << d[2];
      }
  lorenzo3_decode(reinterpret_cast<std::byte*>(residual.data()), d, sizeof(U));
  EXPECT_EQ(residual, u);
}

TEST(BrickCodecPredictorTest, Lorenzo3ResidualIsTheSpecFormula) {
  std::uint32_t seed = 100;
  for (const BrickDims& d : kShapes) {
    expect_spec_residual<float>(d, seed++);
    expect_spec_residual<double>(d, seed++);
  }
  // A hand-checked case: 2x2x2 samples 1..8 (as integers) leave 1 at the origin, the
  // differences along each axis (1, 2, 4) and 0 for the mixed terms, zigzagged to twice
  // that; descending samples give negative residuals, zigzagged to odd numbers.
  std::vector<std::uint32_t> u = {1, 2, 3, 4, 5, 6, 7, 8}, r(8);
  lorenzo3_encode(reinterpret_cast<const std::byte*>(u.data()), reinterpret_cast<std::byte*>(r.data()),
                  {2, 2, 2}, 4);
  EXPECT_EQ(r, (std::vector<std::uint32_t>{2, 2, 4, 0, 8, 0, 0, 0}));
  u = {8, 7, 6, 5, 4, 3, 2, 1};
  lorenzo3_encode(reinterpret_cast<const std::byte*>(u.data()), reinterpret_cast<std::byte*>(r.data()),
                  {2, 2, 2}, 4);
  EXPECT_EQ(r, (std::vector<std::uint32_t>{16, 1, 3, 0, 7, 0, 0, 0}));
}

TEST(BrickCodecPredictorTest, Lorenzo3ShrinksSmoothFields) {
  const BrickDims d{25, 25, 25};
  const auto samples = smooth_samples<float>(d);
  const auto plain = compress_brick(bytes_of(samples), DType::kFloat32, d, {"zstd", 1, "byte", "none"});
  const auto lorenzo = compress_brick(bytes_of(samples), DType::kFloat32, d, {"zstd", 1, "byte", "lorenzo3"});
  EXPECT_LT(lorenzo.size(), plain.size() * 9 / 10) << plain.size() << " vs " << lorenzo.size();
}

TEST(BrickCodecPredictorTest, DamagedChunksAreStillReported) {
  const BrickDims d{9, 8, 7};
  const auto samples = smooth_samples<float>(d);
  const format::CodecSpec codec{"zstd", 1, "byte", "lorenzo3"};
  const auto chunk = compress_brick(bytes_of(samples), DType::kFloat32, d, codec);
  std::vector<std::byte> out(samples.size() * 4);
  expect_error([&] { decompress_brick(std::span(chunk).first(10), DType::kFloat32, d, codec, out, "f: node 3"); },
               ErrorCode::kCorrupt, {"f: node 3", "not a valid Blosc buffer"});
  std::vector<std::byte> bad = chunk;
  bad[4] = std::byte{0x7f};  // uncompressed size field
  expect_error([&] { decompress_brick(bad, DType::kFloat32, d, codec, out, "f: node 3"); },
               ErrorCode::kCorrupt, {"f: node 3"});
  // The same bytes read as a float64 brick of half the samples: wrong type size.
  std::vector<std::byte> wide(9 * 4 * 7 * 8);
  expect_error([&] { decompress_brick(chunk, DType::kFloat64, {9, 4, 7}, codec, wide, "f"); },
               ErrorCode::kCorrupt, {"type size 4"});
}

TEST(BrickCodecPredictorTest, ShapelessCompressionRefusesAPredictor) {
  const std::vector<float> samples(8, 1.f);
  expect_error([&] { compress_brick(bytes_of(samples), DType::kFloat32, {"zstd", 1, "byte", "lorenzo3"}); },
               ErrorCode::kInvalidArgument, {"lorenzo3", "shape"});
  // The Blosc layer alone equals predictor none with a shape.
  const auto a = compress_brick(bytes_of(samples), DType::kFloat32, format::CodecSpec{});
  const auto b = compress_brick(bytes_of(samples), DType::kFloat32, {2, 2, 2}, format::CodecSpec{});
  EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace strielad
