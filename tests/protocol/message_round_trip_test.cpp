// SPDX-License-Identifier: Apache-2.0
// Every message type survives encode_frame / decode_frame unchanged, with the frame
// and field layout of formats/protocol.md.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <set>

#include "core/byte_io.h"
#include "protocol/message_codec.h"
#include "protocol/sample_messages.h"

namespace strielad::protocol {
namespace {

using samples::sample_messages;

std::uint16_t u16_at(const std::vector<std::byte>& b, std::size_t at) {
  std::uint16_t v;
  std::memcpy(&v, b.data() + at, sizeof v);
  return v;
}

std::uint32_t u32_at(const std::vector<std::byte>& b, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, b.data() + at, sizeof v);
  return v;
}

TEST(MessageRoundTripTest, SamplesCoverEveryMessageType) {
  std::set<MessageType> types;
  for (const Message& m : sample_messages()) types.insert(message_type(m));
  EXPECT_EQ(types.size(), std::variant_size_v<Message>);
}

TEST(MessageRoundTripTest, EveryMessageTypeRoundTrips) {
  for (const Message& message : sample_messages()) {
    const MessageType type = message_type(message);
    SCOPED_TRACE(message_type_name(type));
    const std::vector<std::byte> frame = encode_frame(message);
    ASSERT_GE(frame.size(), kFrameHeaderBytes);
    EXPECT_EQ(u32_at(frame, 0), frame.size() - kFrameHeaderBytes);
    EXPECT_EQ(u16_at(frame, 4), static_cast<std::uint16_t>(type));
    EXPECT_EQ(u16_at(frame, 6), 0);
    EXPECT_EQ(decode_frame(frame, kMaxServerPayloadBytes), message);
    // The streaming path: header first, then exactly the payload.
    const FrameHeader header = decode_frame_header(frame, kMaxServerPayloadBytes);
    EXPECT_EQ(header, (FrameHeader{static_cast<std::uint32_t>(frame.size() - 8), type}));
    EXPECT_EQ(peek_payload_length(frame), header.payload_bytes);
    EXPECT_EQ(decode_payload(header, std::span(frame).subspan(kFrameHeaderBytes)), message);
  }
}

TEST(MessageRoundTripTest, ClientFramesFitTheClientLimit) {
  for (const Message& message : sample_messages()) {
    if (!is_client_message(message_type(message))) continue;
    const auto frame = encode_frame(message);
    EXPECT_EQ(decode_frame(frame, kMaxClientPayloadBytes), message);
  }
}

TEST(MessageRoundTripTest, HelloLayoutIsAsSpecified) {
  const auto frame = encode_frame(Hello{1, "ab", "xyz"});
  const std::string expected_payload = std::string("STRIELAD") + std::string("\x01\x00", 2) +
                                       std::string("\x02\x00", 2) + "ab" +
                                       std::string("\x03\x00", 2) + "xyz";
  ASSERT_EQ(frame.size(), 8 + expected_payload.size());
  EXPECT_EQ(u32_at(frame, 0), expected_payload.size());
  EXPECT_EQ(u16_at(frame, 4), 1);
  EXPECT_EQ(std::memcmp(frame.data() + 8, expected_payload.data(), expected_payload.size()), 0);
}

TEST(MessageRoundTripTest, CutUpdateLayoutIsAsSpecified) {
  const auto frame = encode_frame(CutUpdate{9, {{7, 2.5f}}, {8, 10}, {}});
  // generation, added count + 1 entry, removed count + 2 ids, reprioritized count.
  ASSERT_EQ(frame.size(), 8u + 4 + 4 + 8 + 4 + 8 + 4);
  EXPECT_EQ(u32_at(frame, 8), 9u);
  EXPECT_EQ(u32_at(frame, 12), 1u);
  EXPECT_EQ(u32_at(frame, 16), 7u);
  float priority;
  std::memcpy(&priority, frame.data() + 20, 4);
  EXPECT_EQ(priority, 2.5f);
  EXPECT_EQ(u32_at(frame, 24), 2u);
  EXPECT_EQ(u32_at(frame, 28), 8u);
  EXPECT_EQ(u32_at(frame, 32), 10u);
  EXPECT_EQ(u32_at(frame, 36), 0u);
}

TEST(MessageRoundTripTest, WelcomeAndErrorLayoutsAreAsSpecified) {
  const auto welcome = encode_frame(Welcome{1, "s", ServerLimits{100, 200, 30, 4}});
  ASSERT_EQ(welcome.size(), 8u + 18 + 2 + 1);
  EXPECT_EQ(u16_at(welcome, 8), 1);
  EXPECT_EQ(u32_at(welcome, 10), 100u);
  EXPECT_EQ(u32_at(welcome, 14), 200u);
  EXPECT_EQ(u32_at(welcome, 18), 30u);
  EXPECT_EQ(u32_at(welcome, 22), 4u);
  EXPECT_EQ(u16_at(welcome, 26), 1);
  const auto error = encode_frame(ErrorMessage{WireError::kTooLarge, true, "m"});
  ASSERT_EQ(error.size(), 8u + 3 + 2 + 1);
  EXPECT_EQ(u16_at(error, 8), 101);
  EXPECT_EQ(static_cast<int>(error[10]), 1);
  EXPECT_EQ(u16_at(error, 11), 1);
}

TEST(MessageRoundTripTest, StringsAndListsAtTheirLimitsRoundTrip) {
  const Hello hello{1, std::string(kMaxNameBytes, 'n'), std::string(kMaxTokenBytes, 't')};
  EXPECT_EQ(decode_frame(encode_frame(hello), kMaxClientPayloadBytes), Message(hello));
  const SetScene scene{5, std::string(kMaxSceneBytes, ' ')};
  EXPECT_EQ(decode_frame(encode_frame(scene), kMaxClientPayloadBytes), Message(scene));
  const NodeFailed failed{1, 2, WireError::kIo, std::string(kMaxMessageTextBytes, 'm')};
  EXPECT_EQ(decode_frame(encode_frame(failed), kMaxServerPayloadBytes), Message(failed));
  // The largest CutUpdate within the client payload limit.
  CutUpdate update{1, {}, {}, {}};
  const std::size_t entries = (kMaxClientPayloadBytes - 16) / 8;
  for (std::size_t i = 0; i < entries; ++i) {
    update.added.push_back({static_cast<NodeId>(i), static_cast<float>(i)});
  }
  const auto frame = encode_frame(update);
  EXPECT_EQ(frame.size(), 8 + kMaxClientPayloadBytes);
  EXPECT_EQ(decode_frame(frame, kMaxClientPayloadBytes), Message(update));
  NodeResult result{1, 2, {}};
  for (std::uint32_t id = 1; id <= kMaxSubVolumes; ++id) {
    result.subvolumes.push_back({id, NodeOutcome::kSkippedDomain, "", {}, {}});
  }
  EXPECT_EQ(decode_frame(encode_frame(result), kMaxServerPayloadBytes), Message(result));
}

TEST(MessageRoundTripTest, NodeResultMeshIsQuantizedWithinBounds) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> lon(5.25, 5.5), lat(50.0, 50.2), height(20, 3000);
  std::normal_distribution<float> gauss;
  Mesh mesh;
  mesh.subvolume_id = 3;
  mesh.attribute_names = {"ta"};
  mesh.attributes.resize(1);
  for (int i = 0; i < 500; ++i) {
    mesh.positions.push_back({lon(rng), lat(rng), height(rng)});
    mesh.normals.push_back({gauss(rng), gauss(rng), gauss(rng) + 0.01f});
    mesh.attributes[0].push_back(i % 7 == 0 ? std::nanf("") : 250 + gauss(rng));
  }
  for (std::uint32_t i = 0; i + 2 < 500; ++i) {
    mesh.triangles.push_back({i, i + 1, i + 2});
    mesh.face_kinds.push_back(static_cast<FaceKind>(i % 4));
  }
  const NodeResult sent{2, 99, {{3, NodeOutcome::kMesh, "", mesh, {}}}};
  const Message got = decode_frame(encode_frame(sent), kMaxServerPayloadBytes);
  const auto& result = std::get<NodeResult>(got);
  ASSERT_EQ(result.subvolumes.size(), 1u);
  EXPECT_EQ(result.generation, 2u);
  EXPECT_EQ(result.node, 99u);
  const Mesh& back = result.subvolumes[0].mesh;
  EXPECT_TRUE(back.attribute_names.empty());
  EXPECT_EQ(back.subvolume_id, 3u);
  EXPECT_TRUE(samples::mesh_within_bounds(mesh, back));
  EXPECT_NE(back.positions, mesh.positions);  // it was quantized, not copied
}

}  // namespace
}  // namespace strielad::protocol
