// SPDX-License-Identifier: Apache-2.0
// The compact mesh encoding (formats/protocol.md, "Mesh encoding"): sizes, the documented
// quantization error bounds, unit normals from every pair, the index width switch at
// 65,536 vertices, and rejection of every malformed mesh without large allocations.
#include "protocol/mesh_encoding.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>

#include "protocol/sample_messages.h"
#include "support/expect_error.h"

namespace strielad::protocol {
namespace {

using strielad::testing::expect_error;

std::vector<std::byte> encode(const Mesh& mesh) {
  ByteWriter w;
  encode_mesh(mesh, w);
  return w.take();
}

Mesh decode(std::span<const std::byte> bytes) {
  ByteReader in(bytes, "test");
  Mesh mesh = decode_mesh(in, "mesh");
  EXPECT_EQ(in.remaining(), 0u);
  return mesh;
}

double ulp(double x) {
  x = std::abs(x);
  return std::nextafter(x, std::numeric_limits<double>::infinity()) - x;
}

// A strip of `n` vertices in a node-sized box around (lon, lat, height), with a NaN
// every 5th value of the second attribute.
Mesh random_mesh(std::size_t n, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> lon(170.0, 170.2), lat(-47.3, -47.1), height(20, 12000);
  std::normal_distribution<float> gauss;
  Mesh m;
  m.attributes.resize(2);
  for (std::size_t i = 0; i < n; ++i) {
    m.positions.push_back({lon(rng), lat(rng), height(rng)});
    m.normals.push_back({gauss(rng), gauss(rng), gauss(rng) + 1e-3f});
    m.attributes[0].push_back(273.15f + 10 * gauss(rng));
    m.attributes[1].push_back(i % 5 == 0 ? std::numeric_limits<float>::quiet_NaN()
                                         : 1e-5f * std::abs(gauss(rng)));
  }
  for (std::uint32_t i = 0; i + 2 < n; ++i) {
    m.triangles.push_back({i, i + 2, i + 1});
    m.face_kinds.push_back(static_cast<FaceKind>(i % 4));
  }
  return m;
}

double angle_degrees(const std::array<float, 3>& a, const std::array<float, 3>& b) {
  double dot = 0, la = 0, lb = 0;
  for (int i = 0; i < 3; ++i) {
    dot += double{a[i]} * b[i];
    la += double{a[i]} * a[i];
    lb += double{b[i]} * b[i];
  }
  const double c = std::clamp(dot / std::sqrt(la * lb), -1.0, 1.0);
  return std::acos(c) * 180 / std::numbers::pi;
}

TEST(MeshEncodingTest, EncodedSizeMatchesTheFormula) {
  for (const std::size_t n : {3, 1000, 65536, 65537}) {
    const Mesh m = random_mesh(n, 1);
    const std::size_t width = n <= 65536 ? 2 : 4;
    const std::size_t expected = 58 + 10 * n + (3 * width + 1) * (n - 2) + 2 * (8 + 2 * n);
    EXPECT_EQ(encoded_mesh_bytes(m), expected);
    EXPECT_EQ(encode(m).size(), expected);
  }
}

TEST(MeshEncodingTest, PositionsAreWithinHalfAStep) {
  const Mesh m = random_mesh(20000, 2);
  const Mesh back = decode(encode(m));
  ASSERT_EQ(back.positions.size(), m.positions.size());
  for (int a = 0; a < 3; ++a) {
    double lo = m.positions[0][a], hi = lo;
    for (const auto& p : m.positions) lo = std::min(lo, p[a]), hi = std::max(hi, p[a]);
    const double half_step = (hi - lo) / 131070;
    const double bound = half_step + 4 * ulp(std::max(std::abs(lo), std::abs(hi)));
    double worst = 0;
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      worst = std::max(worst, std::abs(back.positions[i][a] - m.positions[i][a]));
      // The box's ends decode exactly.
      if (m.positions[i][a] == lo || m.positions[i][a] == hi) {
        EXPECT_EQ(back.positions[i][a], m.positions[i][a]);
      }
    }
    EXPECT_LE(worst, bound) << "axis " << a;
    EXPECT_GT(worst, 0.5 * half_step) << "axis " << a << ": 20000 random points should use the bound";
  }
}

TEST(MeshEncodingTest, FlatAxisDecodesExactly) {
  Mesh m = samples::exact_mesh(0);
  for (auto& p : m.positions) p[2] = 1234.5;
  m.positions[1][0] = 9.123456789;  // between lo and hi: quantized
  const Mesh back = decode(encode(m));
  for (std::size_t i = 0; i < m.positions.size(); ++i) EXPECT_EQ(back.positions[i][2], 1234.5);
  EXPECT_NEAR(back.positions[1][0], 9.123456789, (14.5 - 4.5) / 131070);
}

TEST(MeshEncodingTest, ExactMeshRoundTripsUnchanged) {
  const Mesh m = samples::exact_mesh(0);
  EXPECT_EQ(decode(encode(m)), m);
}

TEST(MeshEncodingTest, NormalsAreUnitAndWithinTheBound) {
  std::mt19937 rng(3);
  std::normal_distribution<float> gauss;
  std::vector<std::array<float, 3>> directions;
  for (int i = 0; i < 1000000; ++i) directions.push_back({gauss(rng), gauss(rng), gauss(rng)});
  for (const float x : {-1.0f, 0.0f, 1.0f}) {
    for (const float y : {-1.0f, 0.0f, 1.0f}) {
      for (const float z : {-1.0f, -1e-7f, 0.0f, 1e-7f, 1.0f}) {
        if (x != 0 || y != 0 || z != 0) directions.push_back({x, y, z});
      }
    }
  }
  directions.push_back({1e-30f, -1e-30f, -1e-38f});  // tiny but not zero
  double worst = 0;
  for (const auto& n : directions) {
    const auto q = encode_normal(n);
    const auto d = decode_normal(q[0], q[1]);
    const double length = std::sqrt(double{d[0]} * d[0] + double{d[1]} * d[1] + double{d[2]} * d[2]);
    ASSERT_NEAR(length, 1.0, 1e-6);
    worst = std::max(worst, angle_degrees(n, d));
  }
  std::printf("normals: largest angle error %.5f degrees over %zu directions\n", worst,
              directions.size());
  EXPECT_LT(worst, 0.005);
  EXPECT_GT(worst, 0.0005);  // it is quantized: not a bound that holds by accident
}

TEST(MeshEncodingTest, EveryNormalPairDecodesToAUnitVector) {
  std::vector<int> values;
  for (int v = -32768; v <= 32767; v += 251) values.push_back(v);
  for (const int v : {-32768, -32767, -1, 0, 1, 32766, 32767}) values.push_back(v);
  for (const int u : values) {
    for (const int v : values) {
      const auto d = decode_normal(static_cast<std::int16_t>(u), static_cast<std::int16_t>(v));
      ASSERT_TRUE(std::isfinite(d[0]) && std::isfinite(d[1]) && std::isfinite(d[2]));
      const double length =
          std::sqrt(double{d[0]} * d[0] + double{d[1]} * d[1] + double{d[2]} * d[2]);
      ASSERT_NEAR(length, 1.0, 1e-6) << u << ", " << v;
    }
  }
}

TEST(MeshEncodingTest, AttributesAreWithinHalfAStepAndMissingStaysMissing) {
  const Mesh m = random_mesh(20000, 4);
  const Mesh back = decode(encode(m));
  ASSERT_EQ(back.attributes.size(), 2u);
  for (std::size_t a = 0; a < 2; ++a) {
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (const float v : m.attributes[a]) {
      if (!std::isnan(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    }
    const float top = std::max(std::abs(lo), std::abs(hi));
    const double bound = (double{hi} - lo) / 131068 +
                         (std::nextafter(top, std::numeric_limits<float>::infinity()) - top);
    for (std::size_t i = 0; i < m.attributes[a].size(); ++i) {
      const float original = m.attributes[a][i], decoded = back.attributes[a][i];
      ASSERT_EQ(std::isnan(original), std::isnan(decoded)) << a << ", " << i;
      if (!std::isnan(original)) {
        ASSERT_LE(std::abs(double{decoded} - original), bound);
      }
    }
  }
}

TEST(MeshEncodingTest, ConstantAndAllMissingAttributesDecodeExactly) {
  Mesh m = samples::exact_mesh(0);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  m.attributes = {{2.5f, 2.5f, 2.5f, 2.5f}, {nan, nan, nan, nan}};
  const auto bytes = encode(m);
  const std::size_t attributes_at = 58 + 40 + 24 + 4;
  float lo, hi;
  std::memcpy(&lo, bytes.data() + attributes_at + 16, 4);  // second attribute's range
  std::memcpy(&hi, bytes.data() + attributes_at + 20, 4);
  EXPECT_EQ(lo, 0.0f);
  EXPECT_EQ(hi, 0.0f);
  const Mesh back = decode(bytes);
  EXPECT_EQ(back.attributes[0], m.attributes[0]);
  for (const float v : back.attributes[1]) EXPECT_TRUE(std::isnan(v));
}

// A fan of `n` vertices whose last triangle uses the largest index.
Mesh fan(std::size_t n) {
  Mesh m;
  for (std::size_t i = 0; i < n; ++i) {
    m.positions.push_back({static_cast<double>(i), 0.5 * static_cast<double>(i % 3), 1.0});
    m.normals.push_back({0, 0, 1});
  }
  const auto last = static_cast<std::uint32_t>(n - 1);
  m.triangles = {{0, 1, 2}, {0, last - 1, last}};
  m.face_kinds = {FaceKind::kLimit, FaceKind::kLimit};
  return m;
}

TEST(MeshEncodingTest, IndexWidthSwitchesAbove65536Vertices) {
  const Mesh small = fan(65536);
  const auto small_bytes = encode(small);
  EXPECT_EQ(static_cast<int>(small_bytes[9]), 2);
  EXPECT_EQ(decode(small_bytes).triangles, small.triangles);  // index 65535 fits 16 bits

  const Mesh large = fan(65537);
  const auto large_bytes = encode(large);
  EXPECT_EQ(static_cast<int>(large_bytes[9]), 4);
  EXPECT_EQ(decode(large_bytes).triangles, large.triangles);  // index 65536 does not

  auto narrowed = large_bytes;
  narrowed[9] = std::byte{2};
  expect_error([&] { decode(narrowed); }, ErrorCode::kInvalidInput,
               {"mesh: index_bytes: 2 with 65537 vertices (must be 4)"});
  auto widened = small_bytes;
  widened[9] = std::byte{4};
  expect_error([&] { decode(widened); }, ErrorCode::kInvalidInput,
               {"index_bytes: 4 with 65536 vertices (must be 2)"});
  for (const int width : {0, 1, 3, 8}) {
    auto odd = small_bytes;
    odd[9] = static_cast<std::byte>(width);
    expect_error([&] { decode(odd); }, ErrorCode::kInvalidInput, {"index_bytes"});
  }
}

// --- rejection ---------------------------------------------------------------------

template <typename T>
void put(std::vector<std::byte>& bytes, std::size_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof value);
}

void expect_invalid(const std::vector<std::byte>& bytes,
                    std::initializer_list<std::string_view> parts) {
  expect_error([&] { decode(bytes); }, ErrorCode::kInvalidInput, parts);
}

// exact_mesh: 4 vertices, 4 triangles, 2 attributes, 16-bit indices.
constexpr std::size_t kTriangles = 58 + 40;
constexpr std::size_t kFaceKinds = kTriangles + 24;
constexpr std::size_t kAttributes = kFaceKinds + 4;

TEST(MeshEncodingTest, MalformedHeaderIsRejected) {
  const auto good = encode(samples::exact_mesh(0));
  auto bytes = good;
  put<std::uint32_t>(bytes, 4, 0);
  expect_invalid(bytes, {"mesh: triangle_count: 0"});
  bytes = good;
  bytes[8] = std::byte{65};
  expect_invalid(bytes, {"mesh: attribute_count: 65 is over the limit of 64"});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  bytes = good;
  put(bytes, 10, nan);  // lo.x
  expect_invalid(bytes, {"mesh: box: x range"});
  bytes = good;
  put(bytes, 34 + 16, -inf);  // hi.z
  expect_invalid(bytes, {"mesh: box: z range"});
  bytes = good;
  put(bytes, 10 + 8, 60.0);  // lo.y above hi.y = 54.5
  expect_invalid(bytes, {"mesh: box: y range [60, 54.5]"});
  bytes = good;
  put(bytes, 10, -1e308);
  put(bytes, 34, 1e308);  // hi - lo overflows
  expect_invalid(bytes, {"mesh: box: x range"});
}

TEST(MeshEncodingTest, MalformedArraysAreRejected) {
  const auto good = encode(samples::exact_mesh(0));
  auto bytes = good;
  put<std::uint16_t>(bytes, kTriangles + 6 + 4, 4);  // triangles[1][2]
  expect_invalid(bytes, {"mesh: triangles[1][2]: index 4 >= vertex_count 4"});
  bytes = good;
  bytes[kFaceKinds + 3] = std::byte{4};
  expect_invalid(bytes, {"mesh: face_kinds[3]: 4 is not a face kind (0..3)"});
  bytes = good;
  put(bytes, kAttributes, std::numeric_limits<float>::quiet_NaN());
  expect_invalid(bytes, {"mesh: attributes[0]: range"});
  bytes = good;
  put(bytes, kAttributes + 8 + 8 + 4, -2.0f);  // attributes[1].hi below its lo (-1.5)
  expect_invalid(bytes, {"mesh: attributes[1]: range [-1.5, -2]"});
  bytes = good;
  put(bytes, kAttributes + 4, std::numeric_limits<float>::infinity());
  expect_invalid(bytes, {"mesh: attributes[0]: range [250, inf]"});
}

TEST(MeshEncodingTest, EveryTruncationIsRejected) {
  const auto good = encode(samples::exact_mesh(0));
  for (std::size_t n = 0; n < good.size(); ++n) {
    expect_error([&] { decode(std::span(good).first(n)); }, ErrorCode::kTruncated, {"mesh"});
  }
}

TEST(MeshEncodingTest, HugeCountsAreRejectedBeforeAllocating) {
  // 20 bytes claiming 4 billion vertices: the header alone is missing.
  ByteWriter w;
  w.u32(0xFFFFFFFF);
  w.u32(0xFFFFFFFF);
  w.u8(64);
  w.u8(4);
  w.zeros(10);
  expect_error([&] { decode(w.data()); }, ErrorCode::kTruncated,
               {"mesh: the mesh header needs 58 bytes, only 20 remain"});
  // A complete header with such counts: rejected from the counts, nothing allocated
  // (an attempt would throw std::bad_alloc, which expect_error reports).
  w.zeros(38);
  expect_error([&] { decode(w.data()); }, ErrorCode::kTruncated,
               {"4294967295 vertices, 4294967295 triangles and 64 attributes need", "only 0 remain"});
}

TEST(MeshEncodingTest, EncoderRejectsBrokenMeshesAndWritesNothing) {
  const auto expect_rejected = [](const Mesh& m, std::string_view part) {
    ByteWriter w;
    w.u8(7);
    expect_error([&] { encode_mesh(m, w, "node 5"); }, ErrorCode::kInvalidArgument,
                 {"node 5", part});
    EXPECT_EQ(w.size(), 1u);
  };
  expect_rejected(Mesh{}, "triangles: a mesh needs at least one triangle");
  Mesh m = samples::exact_mesh(0);
  m.normals.pop_back();
  expect_rejected(m, "normals: 3 normals for 4 vertices");
  m = samples::exact_mesh(0);
  m.face_kinds.pop_back();
  expect_rejected(m, "face_kinds: 3 face kinds for 4 triangles");
  m = samples::exact_mesh(0);
  m.positions[2][1] = std::nan("");
  expect_rejected(m, "positions[2]: not finite");
  m = samples::exact_mesh(0);
  m.positions[0][0] = -1e308;
  m.positions[1][0] = 1e308;
  expect_rejected(m, "positions: extent along axis 0 overflows");
  m = samples::exact_mesh(0);
  m.normals[3] = {0, 0, 0};
  expect_rejected(m, "normals[3]: zero length or not finite");
  m = samples::exact_mesh(0);
  m.normals[1] = {std::nanf(""), 0, 1};
  expect_rejected(m, "normals[1]");
  m = samples::exact_mesh(0);
  m.triangles[2][0] = 4;
  expect_rejected(m, "triangles[2][0]: index 4 >= vertex count 4");
  m = samples::exact_mesh(0);
  m.face_kinds[1] = static_cast<FaceKind>(9);
  expect_rejected(m, "face_kinds[1]: 9 is not a face kind");
  m = samples::exact_mesh(0);
  m.attributes[1].pop_back();
  expect_rejected(m, "attributes[1]: 3 values for 4 vertices");
  m = samples::exact_mesh(0);
  m.attributes[0][2] = -std::numeric_limits<float>::infinity();
  expect_rejected(m, "attributes[0][2]: infinite");
  m = samples::exact_mesh(0);
  m.attributes.assign(65, std::vector<float>(4, 0.0f));
  expect_rejected(m, "attributes: 65 attributes, over the limit of 64");
}

}  // namespace
}  // namespace strielad::protocol
