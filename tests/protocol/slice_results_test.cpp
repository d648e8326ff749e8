// SPDX-License-Identifier: Apache-2.0
// Slice results in NodeResult (formats/protocol.md version 2): they round-trip behind
// the frame's slices flag, a frame without slices is a version-1 frame byte for byte,
// and corrupt or truncated slice parts are rejected naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "protocol/mesh_encoding.h"
#include "protocol/message_codec.h"
#include "support/expect_error.h"

namespace strielad::protocol {
namespace {

using strielad::testing::expect_error;

Mesh slice_mesh() {
  Mesh m;
  m.positions = {{5.0, 50.0, 500.0}, {6.0, 50.0, 500.0}, {6.0, 51.0, 500.0}, {5.0, 51.0, 500.0}};
  m.normals.assign(4, {0, 0, 1});
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.face_kinds.assign(2, FaceKind::kSlice);
  m.attributes = {{250.0f, 260.0f, std::numeric_limits<float>::quiet_NaN(), 255.0f}};
  return m;
}

NodeResult result_with_slices() {
  NodeResult r;
  r.generation = 3;
  r.node = 17;
  r.subvolumes.push_back({1, NodeOutcome::kEmpty, "", {}, {}});
  r.slices.push_back({4, NodeOutcome::kMesh, "", slice_mesh()});
  r.slices.push_back({5, NodeOutcome::kSkippedDomain, "plane lat = 2 misses the node", {}});
  return r;
}

std::uint16_t flags_of(const std::vector<std::byte>& frame) {
  return static_cast<std::uint16_t>(std::to_integer<unsigned>(frame[6]) |
                                    std::to_integer<unsigned>(frame[7]) << 8);
}

TEST(SliceResultsTest, RoundTripBehindTheSlicesFlag) {
  const NodeResult r = result_with_slices();
  const auto frame = encode_frame(r);
  EXPECT_EQ(flags_of(frame), kFrameFlagSlices);
  const auto back = std::get<NodeResult>(decode_frame(frame, kMaxServerPayloadBytes));
  ASSERT_EQ(back.slices.size(), 2u);
  EXPECT_EQ(back.slices[0].slice_id, 4u);
  EXPECT_EQ(back.slices[0].mesh.subvolume_id, 4u);
  EXPECT_EQ(back.slices[0].mesh.face_kinds, slice_mesh().face_kinds);
  ASSERT_EQ(back.slices[0].mesh.attributes.size(), 1u);
  EXPECT_NEAR(back.slices[0].mesh.attributes[0][1], 260.0f, 1e-3);
  EXPECT_TRUE(std::isnan(back.slices[0].mesh.attributes[0][2]));
  for (std::size_t v = 0; v < 4; ++v) EXPECT_EQ(back.slices[0].mesh.positions[v], slice_mesh().positions[v]);
  EXPECT_EQ(back.slices[1].outcome, NodeOutcome::kSkippedDomain);
  EXPECT_EQ(back.slices[1].reason, "plane lat = 2 misses the node");
  EXPECT_EQ(encode_frame(back), frame);
}

TEST(SliceResultsTest, WithoutSlicesTheFrameIsAVersion1Frame) {
  NodeResult r = result_with_slices();
  r.slices.clear();
  const auto frame = encode_frame(r);
  EXPECT_EQ(flags_of(frame), 0);
  // The version-1 layout: the payload ends after the sub-volume results.
  EXPECT_EQ(frame.size(), kFrameHeaderBytes + 12 + 7);
  EXPECT_TRUE(std::get<NodeResult>(decode_frame(frame, kMaxServerPayloadBytes)).slices.empty());
}

TEST(SliceResultsTest, FlagIsOnlyAllowedOnNodeResult) {
  auto frame = encode_frame(Stats{"{}"});
  frame[6] = std::byte{1};
  expect_error([&] { decode_frame(frame, kMaxServerPayloadBytes); }, ErrorCode::kInvalidInput,
               {"frame header", "flags", "must be 0"});
  auto result = encode_frame(result_with_slices());
  result[6] = std::byte{3};
  expect_error([&] { decode_frame(result, kMaxServerPayloadBytes); }, ErrorCode::kInvalidInput,
               {"flags", "0x0003"});
}

TEST(SliceResultsTest, FlagWithoutAListIsTruncated) {
  NodeResult r = result_with_slices();
  r.slices.clear();
  auto frame = encode_frame(r);
  frame[6] = std::byte{1};
  expect_error([&] { decode_frame(frame, kMaxServerPayloadBytes); }, ErrorCode::kTruncated, {"NodeResult", "slices"});
}

// Offsets into the frame of result_with_slices(): header 8, generation/node/count 12,
// sub-volume result 7, slice count 4, slice id 4, outcome 1, reason 2.
constexpr std::size_t kSliceCount = 8 + 12 + 7;
constexpr std::size_t kFirstSliceId = kSliceCount + 4;
constexpr std::size_t kFirstMesh = kFirstSliceId + 4 + 1 + 2;

TEST(SliceResultsTest, CorruptSliceParts) {
  const auto good = encode_frame(result_with_slices());
  auto bad = good;
  std::memset(&bad[kSliceCount], 0, 4);
  expect_error([&] { decode_frame(bad, kMaxServerPayloadBytes); }, ErrorCode::kInvalidInput,
               {"slices", "0 entries with the slices flag"});
  bad = good;
  bad[kSliceCount] = std::byte{17};
  expect_error([&] { decode_frame(bad, kMaxServerPayloadBytes); }, ErrorCode::kInvalidInput,
               {"slices", "17 entries, over the limit of 16"});
  bad = good;
  std::memset(&bad[kFirstSliceId], 0, 4);
  expect_error([&] { decode_frame(bad, kMaxServerPayloadBytes); }, ErrorCode::kInvalidInput,
               {"slices[0].slice_id"});
  bad = good;
  bad[kFirstSliceId] = std::byte{5};  // equals the second slice's id
  expect_error([&] { decode_frame(bad, kMaxServerPayloadBytes); }, ErrorCode::kInvalidInput,
               {"slices[1].slice_id", "also at slices[0]"});
  bad = good;
  bad[kFirstSliceId + 4] = std::byte{9};
  expect_error([&] { decode_frame(bad, kMaxServerPayloadBytes); }, ErrorCode::kInvalidInput,
               {"slices[0].outcome", "not an outcome"});
  bad = good;
  bad[kFirstMesh + 8] = std::byte{2};  // attribute_count
  expect_error([&] { decode_frame(bad, kMaxServerPayloadBytes); }, ErrorCode::kInvalidInput,
               {"slices[0].mesh", "attribute_count", "exactly 1"});
  // A face kind of a sub-volume (0) in a slice mesh.
  const std::size_t face_kinds = kFirstMesh + kMeshHeaderBytes + 10 * 4 + 3 * 2 * 2;
  bad = good;
  ASSERT_EQ(bad[face_kinds], std::byte{4});
  bad[face_kinds] = std::byte{0};
  expect_error([&] { decode_frame(bad, kMaxServerPayloadBytes); }, ErrorCode::kInvalidInput,
               {"slices[0].mesh", "face_kinds[0]", "4 for a slice"});
}

TEST(SliceResultsTest, TruncatedAnywhereInTheSlicesIsRejected) {
  const auto good = encode_frame(result_with_slices());
  for (std::size_t cut = kSliceCount; cut < good.size(); ++cut) {
    std::vector<std::byte> frame(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(cut));
    const std::uint32_t payload = static_cast<std::uint32_t>(cut - kFrameHeaderBytes);
    std::memcpy(frame.data(), &payload, 4);  // little-endian hosts only, as the codec tests
    try {
      decode_frame(frame, kMaxServerPayloadBytes);
      ADD_FAILURE() << "accepted a frame cut at " << cut;
    } catch (const Error& e) {
      EXPECT_TRUE(e.code() == ErrorCode::kTruncated || e.code() == ErrorCode::kInvalidInput) << e.what();
    }
  }
}

TEST(SliceResultsTest, EncoderRefusesWhatADecoderRejects) {
  NodeResult r = result_with_slices();
  r.slices[0].mesh.face_kinds[0] = FaceKind::kLimit;
  expect_error([&] { encode_frame(r); }, ErrorCode::kInvalidArgument, {"slices[0].mesh", "face_kinds[0]"});
  r = result_with_slices();
  r.slices[0].mesh.attributes.push_back(r.slices[0].mesh.attributes[0]);
  expect_error([&] { encode_frame(r); }, ErrorCode::kInvalidArgument, {"slices[0].mesh", "exactly 1"});
  r = result_with_slices();
  r.slices[1].slice_id = 4;
  expect_error([&] { encode_frame(r); }, ErrorCode::kInvalidArgument, {"slices[1].slice_id"});
  r = result_with_slices();
  r.slices.resize(17, r.slices[1]);
  expect_error([&] { encode_frame(r); }, ErrorCode::kInvalidArgument, {"slices", "over the limit of 16"});
}

}  // namespace
}  // namespace strielad::protocol
