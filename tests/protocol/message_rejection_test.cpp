// SPDX-License-Identifier: Apache-2.0
// Every frame formats/protocol.md ("What a peer must reject") rejects is rejected by the
// decoder with the right code and a message naming the message type and field, and
// encode_frame refuses to produce such frames. Frames are built by hand here, since
// encode_frame cannot make them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "core/byte_io.h"
#include "protocol/message_codec.h"
#include "protocol/sample_messages.h"
#include "support/expect_error.h"

namespace strielad::protocol {
namespace {

using strielad::testing::expect_error;

std::vector<std::byte> frame_of(MessageType type, const ByteWriter& payload,
                                std::uint16_t flags = 0) {
  ByteWriter f;
  f.u32(static_cast<std::uint32_t>(payload.size()));
  f.u16(static_cast<std::uint16_t>(type));
  f.u16(flags);
  f.bytes(payload.data());
  return f.take();
}

void put_str16(ByteWriter& w, std::string_view s) {
  w.u16(static_cast<std::uint16_t>(s.size()));
  w.text(s);
}

void put_str32(ByteWriter& w, std::string_view s) {
  w.u32(static_cast<std::uint32_t>(s.size()));
  w.text(s);
}

ByteWriter hello_payload(std::string_view name, std::string_view token,
                         std::uint16_t version = 1) {
  ByteWriter w;
  w.text("STRIELAD");
  w.u16(version);
  put_str16(w, name);
  put_str16(w, token);
  return w;
}

void expect_invalid(const std::vector<std::byte>& frame,
                    std::initializer_list<std::string_view> parts) {
  expect_error([&] { decode_frame(frame, kMaxServerPayloadBytes); }, ErrorCode::kInvalidInput,
               parts);
}

void expect_unencodable(const Message& message, std::initializer_list<std::string_view> parts) {
  expect_error([&] { encode_frame(message); }, ErrorCode::kInvalidArgument, parts);
}

// --- frame header ------------------------------------------------------------------

TEST(MessageRejectionTest, OversizedFrameIsRejectedFromItsHeaderAlone) {
  ByteWriter h;
  h.u32(kMaxClientPayloadBytes + 1);
  h.u16(static_cast<std::uint16_t>(MessageType::kSetScene));
  h.u16(0);
  const auto header = h.take();  // 8 bytes, no payload at all
  EXPECT_EQ(peek_payload_length(header), kMaxClientPayloadBytes + 1);
  expect_error([&] { decode_frame_header(header, kMaxClientPayloadBytes); },
               ErrorCode::kInvalidInput,
               {"frame header: payload_length", "2097153 bytes, over the limit of 2097152"});
  // Not "truncated": the length alone decides, before the missing payload matters.
  expect_error([&] { decode_frame(header, kMaxClientPayloadBytes); }, ErrorCode::kInvalidInput,
               {"payload_length"});
  EXPECT_EQ(decode_frame_header(header, kMaxClientPayloadBytes + 1).payload_bytes,
            kMaxClientPayloadBytes + 1);
}

TEST(MessageRejectionTest, UnknownMessageTypeIsRejected) {
  for (const std::uint16_t type : {0, 8, 100, 108, 0xFFFF}) {
    ByteWriter h;
    h.u32(0);
    h.u16(type);
    h.u16(0);
    expect_error([&] { decode_frame_header(h.data(), 64); }, ErrorCode::kInvalidInput,
                 {"frame header: type", std::to_string(type), "is not a message type"});
  }
  expect_error([&] { decode_payload(FrameHeader{0, static_cast<MessageType>(55)}, {}); },
               ErrorCode::kInvalidInput, {"55 is not a message type"});
}

TEST(MessageRejectionTest, NonZeroFlagsAreRejected) {
  for (const std::uint16_t flags : {1, 0x8000}) {
    expect_invalid(frame_of(MessageType::kGoodbye, ByteWriter{}, flags),
                   {"frame header: flags", "must be 0"});
  }
}

TEST(MessageRejectionTest, ShortHeaderIsTruncated) {
  const auto frame = encode_frame(Goodbye{});
  for (std::size_t n = 0; n < kFrameHeaderBytes; ++n) {
    const auto prefix = std::span(frame).first(n);
    expect_error([&] { decode_frame_header(prefix, 64); }, ErrorCode::kTruncated,
                 {"frame header", "needs 8 bytes"});
    expect_error([&] { peek_payload_length(prefix); }, ErrorCode::kTruncated, {"frame header"});
  }
}

// --- truncation and trailing bytes --------------------------------------------------

TEST(MessageRejectionTest, EveryPrefixOfEveryFrameIsTruncated) {
  for (const Message& message : samples::sample_messages()) {
    SCOPED_TRACE(message_type_name(message_type(message)));
    const auto frame = encode_frame(message);
    for (std::size_t n = 0; n < frame.size(); ++n) {
      expect_error([&] { decode_frame(std::span(frame).first(n), kMaxServerPayloadBytes); },
                   ErrorCode::kTruncated, {});
    }
  }
}

// A payload cut short whose header agrees with the cut length: the fields themselves
// must notice.
TEST(MessageRejectionTest, EveryPrefixOfEveryPayloadIsTruncated) {
  for (const Message& message : samples::sample_messages()) {
    const MessageType type = message_type(message);
    SCOPED_TRACE(message_type_name(type));
    const auto frame = encode_frame(message);
    const auto payload = std::span(frame).subspan(kFrameHeaderBytes);
    for (std::size_t n = 0; n < payload.size(); ++n) {
      expect_error(
          [&] { decode_payload(FrameHeader{static_cast<std::uint32_t>(n), type}, payload.first(n)); },
          ErrorCode::kTruncated, {message_type_name(type)});
    }
  }
}

TEST(MessageRejectionTest, PayloadShorterOrLongerThanItsHeaderIsRejected) {
  const auto frame = encode_frame(SetTime{1, 2});
  const auto payload = std::span(frame).subspan(kFrameHeaderBytes);
  expect_error([&] { decode_payload(FrameHeader{9, MessageType::kSetTime}, payload); },
               ErrorCode::kTruncated, {"SetTime", "payload has 8 bytes, the header announces 9"});
  expect_error([&] { decode_payload(FrameHeader{7, MessageType::kSetTime}, payload); },
               ErrorCode::kInvalidArgument, {"SetTime"});
}

TEST(MessageRejectionTest, BytesAfterThePayloadAreRejected) {
  auto frame = encode_frame(Hello{});
  frame.push_back(std::byte{0});
  expect_invalid(frame, {"frame: 1 bytes after the Hello payload"});
}

TEST(MessageRejectionTest, BytesAfterTheLastFieldAreRejected) {
  for (const Message& message : samples::sample_messages()) {
    const MessageType type = message_type(message);
    SCOPED_TRACE(message_type_name(type));
    auto frame = encode_frame(message);
    frame.push_back(std::byte{0});
    const auto length = static_cast<std::uint32_t>(frame.size() - kFrameHeaderBytes);
    std::memcpy(frame.data(), &length, 4);
    expect_invalid(frame, {message_type_name(type), "1 bytes after the last field"});
  }
}

// --- Hello and Welcome -------------------------------------------------------------

TEST(MessageRejectionTest, HelloWithWrongMagicIsRejected) {
  auto frame = encode_frame(Hello{});
  frame[8] = std::byte{'s'};
  expect_invalid(frame, {"Hello: magic", "73545249454c4144", "is not \"STRIELAD\""});
}

TEST(MessageRejectionTest, HelloVersionZeroIsRejected) {
  expect_invalid(frame_of(MessageType::kHello, hello_payload("c", "", 0)),
                 {"Hello: version: 0"});
  expect_unencodable(Hello{0, "", ""}, {"encode Hello: version: 0"});
}

TEST(MessageRejectionTest, WelcomeWithAVersionOrLimitOutOfRangeIsRejected) {
  const auto welcome = [](std::uint16_t version, ServerLimits limits) {
    ByteWriter w;
    w.u16(version);
    w.u32(limits.max_payload_bytes);
    w.u32(limits.max_nodes_per_update);
    w.u32(limits.max_subvolumes);
    w.u32(limits.max_limits_per_subvolume);
    put_str16(w, "s");
    return frame_of(MessageType::kWelcome, w);
  };
  expect_invalid(welcome(0, {}), {"Welcome: version: 0"});
  expect_invalid(welcome(3, {}), {"Welcome: version: 3"});
  expect_invalid(welcome(1, {0, 1, 1, 1}), {"Welcome: limits.max_payload_bytes: 0"});
  expect_invalid(welcome(1, {kMaxClientPayloadBytes + 1, 1, 1, 1}),
                 {"limits.max_payload_bytes: 2097153 is outside 1 ..= 2097152"});
  expect_invalid(welcome(1, {1, kMaxNodesPerUpdate + 1, 1, 1}), {"limits.max_nodes_per_update"});
  expect_invalid(welcome(1, {1, 1, 65, 1}), {"limits.max_subvolumes: 65"});
  expect_invalid(welcome(1, {1, 1, 1, 0}), {"limits.max_limits_per_subvolume: 0"});
  expect_invalid(welcome(1, {1, 1, 1, 17}), {"limits.max_limits_per_subvolume: 17"});
  expect_unencodable(Welcome{3, "", {}}, {"encode Welcome: version: 3"});
  expect_unencodable(Welcome{1, "", {1, 0, 1, 1}}, {"encode Welcome: limits.max_nodes_per_update"});
}

// --- strings -----------------------------------------------------------------------

TEST(MessageRejectionTest, StringsOverTheirLimitAreRejected) {
  expect_invalid(frame_of(MessageType::kHello, hello_payload(std::string(1025, 'n'), "")),
                 {"Hello: client_name: 1025 bytes, over the limit of 1024"});
  expect_invalid(frame_of(MessageType::kHello, hello_payload("", std::string(4097, 't'))),
                 {"Hello: token: 4097 bytes, over the limit of 4096"});
  ByteWriter open;
  put_str16(open, std::string(1025, 'd'));
  expect_invalid(frame_of(MessageType::kOpenDataset, open), {"OpenDataset: name: 1025 bytes"});
  ByteWriter scene;
  scene.u32(1);
  put_str32(scene, std::string(kMaxSceneBytes + 1, ' '));
  expect_invalid(frame_of(MessageType::kSetScene, scene),
                 {"SetScene: scene_json: 1048577 bytes, over the limit of 1048576"});
  ByteWriter started;
  started.u32(1);
  started.u32(0);
  put_str32(started, std::string(kMaxSceneBytes + 1, ' '));
  expect_invalid(frame_of(MessageType::kGenerationStarted, started),
                 {"GenerationStarted: scene_json: 1048577 bytes"});
  ByteWriter opened;
  put_str16(opened, std::string(1025, 'd'));
  opened.u32(0);
  expect_invalid(frame_of(MessageType::kDatasetOpened, opened), {"DatasetOpened: name: 1025"});
  ByteWriter failed;
  failed.u32(1);
  failed.u32(2);
  failed.u16(static_cast<std::uint16_t>(WireError::kIo));
  put_str16(failed, std::string(4097, 'm'));
  expect_invalid(frame_of(MessageType::kNodeFailed, failed), {"NodeFailed: message: 4097 bytes"});
  ByteWriter error;
  error.u16(static_cast<std::uint16_t>(WireError::kIo));
  error.u8(0);
  put_str16(error, std::string(4097, 'm'));
  expect_invalid(frame_of(MessageType::kError, error), {"Error: message: 4097 bytes"});
  ByteWriter result;
  result.u32(1);
  result.u32(2);
  result.u32(1);
  result.u32(1);
  result.u8(static_cast<std::uint8_t>(NodeOutcome::kSkippedDomain));
  put_str16(result, std::string(4097, 'r'));
  expect_invalid(frame_of(MessageType::kNodeResult, result),
                 {"NodeResult: subvolumes[0].reason: 4097 bytes"});

  expect_unencodable(OpenDataset{std::string(1025, 'd')}, {"encode OpenDataset: name: 1025 bytes"});
  expect_unencodable(SetScene{1, std::string(kMaxSceneBytes + 1, ' ')},
                     {"encode SetScene: scene_json"});
  expect_unencodable(ErrorMessage{WireError::kIo, false, std::string(4097, 'm')},
                     {"encode Error: message: 4097 bytes"});
}

TEST(MessageRejectionTest, StringLengthOverTheLimitIsRejectedBeforeReadingTheString) {
  ByteWriter w;
  w.text("STRIELAD");
  w.u16(1);
  w.u16(60000);  // and no bytes follow
  expect_invalid(frame_of(MessageType::kHello, w), {"Hello: client_name: 60000 bytes"});
}

TEST(MessageRejectionTest, InvalidUtf8IsRejected) {
  const std::pair<std::string, std::size_t> bad[] = {
      {"\x80", 0},                      // lone continuation byte
      {"ab\xC3", 2},                    // sequence cut off
      {"\xC3(", 0},                     // non-continuation inside a sequence
      {"\xC0\xAF", 0},                  // overlong '/'
      {"\xE0\x80\xAF", 0},              // overlong, three bytes
      {"\xF0\x80\x80\xAF", 0},          // overlong, four bytes
      {"x\xED\xA0\x80", 1},             // surrogate U+D800
      {"\xF4\x90\x80\x80", 0},          // U+110000
      {"\xF8\x88\x80\x80\x80", 0},      // five-byte form
      {"ok\xFF", 2},
  };
  for (const auto& [text, at] : bad) {
    ByteWriter w;
    put_str16(w, text);
    expect_invalid(frame_of(MessageType::kOpenDataset, w),
                   {"OpenDataset: name: not valid UTF-8 at byte " + std::to_string(at)});
    expect_unencodable(OpenDataset{text}, {"encode OpenDataset: name: not valid UTF-8"});
  }
  const std::string good[] = {std::string("\0", 1), "\x7F", "\xC2\x80", "\xED\x9F\xBF",
                              "\xEE\x80\x80", "\xEF\xBF\xBF", "\xF0\x90\x80\x80",
                              "\xF4\x8F\xBF\xBF"};
  for (const std::string& text : good) {
    EXPECT_EQ(decode_frame(encode_frame(OpenDataset{text}), 4096), Message(OpenDataset{text}));
  }
  ByteWriter stats;
  put_str32(stats, "{\"k\":\"\xC0\xAF\"}");
  expect_invalid(frame_of(MessageType::kStats, stats), {"Stats: json: not valid UTF-8 at byte 6"});
  expect_unencodable(Hello{1, "", "\xFF"}, {"encode Hello: token: not valid UTF-8"});
}

// --- CutUpdate ---------------------------------------------------------------------

ByteWriter cut_update(const std::vector<NodePriority>& added, const std::vector<NodeId>& removed,
                      const std::vector<NodePriority>& reprioritized) {
  ByteWriter w;
  w.u32(1);
  w.u32(static_cast<std::uint32_t>(added.size()));
  for (const auto& e : added) w.u32(e.node), w.f32(e.priority);
  w.u32(static_cast<std::uint32_t>(removed.size()));
  for (const NodeId n : removed) w.u32(n);
  w.u32(static_cast<std::uint32_t>(reprioritized.size()));
  for (const auto& e : reprioritized) w.u32(e.node), w.f32(e.priority);
  return w;
}

TEST(MessageRejectionTest, CutUpdateListOverTheLimitIsRejectedBeforeReadingIt) {
  ByteWriter w;
  w.u32(1);
  w.u32(kMaxNodesPerUpdate + 1);
  expect_invalid(frame_of(MessageType::kCutUpdate, w),
                 {"CutUpdate: added: 262145 entries, over the limit of 262144"});
  CutUpdate update{1, {}, std::vector<NodeId>(kMaxNodesPerUpdate + 1), {}};
  for (std::size_t i = 0; i < update.removed.size(); ++i) update.removed[i] = static_cast<NodeId>(i);
  expect_unencodable(update, {"encode CutUpdate: removed: 262145 entries"});
}

TEST(MessageRejectionTest, CountLargerThanTheRemainingBytesIsTruncated) {
  ByteWriter w;
  w.u32(1);
  w.u32(0);
  w.u32(1000);  // removed: 1000 ids, 4000 bytes, and only 8 bytes follow
  w.u32(0);
  w.u32(0);
  expect_error([&] { decode_frame(frame_of(MessageType::kCutUpdate, w), kMaxClientPayloadBytes); },
               ErrorCode::kTruncated,
               {"CutUpdate: removed: 1000 entries need 4000 bytes, only 8 remain"});
  ByteWriter r;
  r.u32(1);
  r.u32(2);
  r.u32(64);  // NodeResult: 64 results need at least 448 bytes
  expect_error([&] { decode_frame(frame_of(MessageType::kNodeResult, r), kMaxServerPayloadBytes); },
               ErrorCode::kTruncated, {"NodeResult: subvolumes: 64 entries need 448 bytes"});
}

TEST(MessageRejectionTest, NonFinitePriorityIsRejected) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  expect_invalid(frame_of(MessageType::kCutUpdate, cut_update({{1, 0}, {2, nan}}, {}, {})),
                 {"CutUpdate: added[1].priority: not finite"});
  expect_invalid(frame_of(MessageType::kCutUpdate, cut_update({}, {}, {{3, -inf}})),
                 {"CutUpdate: reprioritized[0].priority: not finite"});
  expect_unencodable(CutUpdate{1, {}, {}, {{3, inf}}},
                     {"encode CutUpdate: reprioritized[0].priority: not finite"});
}

TEST(MessageRejectionTest, NodeListedTwiceInOneCutUpdateIsRejected) {
  expect_invalid(frame_of(MessageType::kCutUpdate, cut_update({{5, 1}, {6, 1}, {5, 2}}, {}, {})),
                 {"CutUpdate: added[2].node: node 5 is also listed at added[0]"});
  expect_invalid(frame_of(MessageType::kCutUpdate, cut_update({}, {7, 8, 7}, {})),
                 {"CutUpdate: removed[2].node: node 7 is also listed at removed[0]"});
  expect_invalid(frame_of(MessageType::kCutUpdate, cut_update({{9, 1}}, {9}, {})),
                 {"CutUpdate: removed[0].node: node 9 is also listed at added[0]"});
  expect_invalid(
      frame_of(MessageType::kCutUpdate, cut_update({}, {4294967295u}, {{4294967295u, 0}})),
      {"reprioritized[0].node: node 4294967295 is also listed at removed[0]"});
  expect_unencodable(CutUpdate{1, {{1, 0}}, {}, {{1, 0}}},
                     {"encode CutUpdate: reprioritized[0].node: node 1 is also listed at added[0]"});
}

// --- NodeResult --------------------------------------------------------------------

ByteWriter node_result(const std::vector<std::pair<std::uint32_t, std::uint8_t>>& results) {
  ByteWriter w;
  w.u32(1);
  w.u32(2);
  w.u32(static_cast<std::uint32_t>(results.size()));
  for (const auto& [id, outcome] : results) {
    w.u32(id);
    w.u8(outcome);
    put_str16(w, "");
  }
  return w;
}

TEST(MessageRejectionTest, NodeResultWithBadSubVolumesIsRejected) {
  std::vector<std::pair<std::uint32_t, std::uint8_t>> many;
  for (std::uint32_t id = 1; id <= 65; ++id) many.push_back({id, 1});
  expect_invalid(frame_of(MessageType::kNodeResult, node_result(many)),
                 {"NodeResult: subvolumes: 65 entries, over the limit of 64"});
  expect_invalid(frame_of(MessageType::kNodeResult, node_result({{0, 1}})),
                 {"NodeResult: subvolumes[0].subvolume_id: 0 is outside 1 ..= 65535"});
  expect_invalid(frame_of(MessageType::kNodeResult, node_result({{1, 1}, {65536, 1}})),
                 {"NodeResult: subvolumes[1].subvolume_id: 65536"});
  expect_invalid(frame_of(MessageType::kNodeResult, node_result({{2, 1}, {3, 2}, {2, 3}})),
                 {"NodeResult: subvolumes[2].subvolume_id: 2 is also at subvolumes[0]"});
  expect_invalid(frame_of(MessageType::kNodeResult, node_result({{1, 5}})),
                 {"NodeResult: subvolumes[0].outcome: 5 is not an outcome"});

  expect_unencodable(NodeResult{1, 2, {{0, NodeOutcome::kEmpty, "", {}, {}}}},
                     {"encode NodeResult: subvolumes[0].subvolume_id: 0"});
  expect_unencodable(NodeResult{1, 2, {{1, static_cast<NodeOutcome>(9), "", {}, {}}}},
                     {"encode NodeResult: subvolumes[0].outcome: 9"});
  expect_unencodable(NodeResult{1, 2, {{1, NodeOutcome::kMesh, "", {}, {}}}},
                     {"encode NodeResult: subvolumes[0].mesh", "at least one triangle"});
  expect_unencodable(NodeResult{1, 2, {{1, NodeOutcome::kEmpty, "", samples::exact_mesh(1), {}}}},
                     {"encode NodeResult: subvolumes[0].mesh: 4 triangles with outcome"});
}

TEST(MessageRejectionTest, MeshErrorsNameTheResult) {
  NodeResult result{1, 2, {{9, NodeOutcome::kEmpty, "", {}, {}}, {3, NodeOutcome::kMesh, "", samples::exact_mesh(3), {}}}};
  auto frame = encode_frame(result);
  // payload: 12 bytes, result 0 (7), result 1's id, outcome and reason (7), then the mesh.
  const std::size_t mesh_at = kFrameHeaderBytes + 12 + 7 + 7;
  ASSERT_EQ(static_cast<int>(frame[mesh_at]), 4);  // vertex_count
  auto kinds = frame;
  kinds[mesh_at + 58 + 40 + 24 + 2] = std::byte{7};  // face_kinds[2]
  expect_invalid(kinds, {"NodeResult: subvolumes[1].mesh: face_kinds[2]: 7 is not a face kind"});
  auto count = frame;
  count[mesh_at] = std::byte{0xFF}, count[mesh_at + 1] = std::byte{0xFF};  // 65535 vertices
  expect_error([&] { decode_frame(count, kMaxServerPayloadBytes); }, ErrorCode::kTruncated,
               {"NodeResult: subvolumes[1].mesh: 65535 vertices, 4 triangles and 2 attributes need"});
}

// --- NodeFailed and Error ----------------------------------------------------------

TEST(MessageRejectionTest, UnknownErrorCodeAndBadFatalFlagAreRejected) {
  for (const std::uint16_t code : {0, 12, 99, 107, 0xFFFF}) {
    ByteWriter failed;
    failed.u32(1);
    failed.u32(2);
    failed.u16(code);
    put_str16(failed, "");
    expect_invalid(frame_of(MessageType::kNodeFailed, failed),
                   {"NodeFailed: code: " + std::to_string(code) + " is not an error code"});
    ByteWriter error;
    error.u16(code);
    error.u8(1);
    put_str16(error, "");
    expect_invalid(frame_of(MessageType::kError, error), {"Error: code: " + std::to_string(code)});
  }
  ByteWriter error;
  error.u16(static_cast<std::uint16_t>(WireError::kIo));
  error.u8(2);
  put_str16(error, "");
  expect_invalid(frame_of(MessageType::kError, error), {"Error: fatal: 2 (must be 0 or 1)"});
  expect_unencodable(NodeFailed{1, 2, static_cast<WireError>(12), ""},
                     {"encode NodeFailed: code: 12 is not an error code"});
  expect_unencodable(ErrorMessage{static_cast<WireError>(0), true, ""}, {"encode Error: code: 0"});
}

TEST(MessageRejectionTest, PayloadOverTheDirectionsLimitIsNotEncoded) {
  CutUpdate update{1, {}, {}, {}};
  for (std::uint32_t i = 0; i < (kMaxClientPayloadBytes - 16) / 8 + 1; ++i) {
    update.added.push_back({i, 0});
  }
  expect_unencodable(update,
                     {"encode CutUpdate: payload of 2097160 bytes is over the limit of 2097152"});
}

}  // namespace
}  // namespace strielad::protocol
