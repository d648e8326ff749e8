// SPDX-License-Identifier: Apache-2.0
// Frames and payloads of the client/server protocol (formats/protocol.md): a frame is an
// 8-byte header (u32 payload length, u16 message type, u16 flags = 0) and the payload.
// Pure functions over byte spans, no sockets, so that every decoder can be fuzzed.
//
// Errors are strielad::Error:
//   kTruncated     the bytes end before a field, or a count needs more bytes than remain;
//   kInvalidInput  anything else formats/protocol.md says to reject; the message starts
//                  with the message type and names the field
//                  ("CutUpdate: added[3].priority: not finite");
//   kInvalidArgument  encode_frame was given a message that breaks those rules (it never
//                  produces a frame a peer must reject), or a caller broke a precondition.
// A peer answers every decoding failure with WireError::kMalformedMessage, except a
// frame whose header announces a payload over its limit: that is kTooLarge, and is
// known from the header alone. To tell the two apart, compare peek_payload_length()
// with the limit before calling decode_frame_header():
//
//   if (peek_payload_length(header) > limit) -> answer kTooLarge, close, read no payload
//   const FrameHeader h = decode_frame_header(header, limit);  // throws: kMalformedMessage
//   ... read exactly h.payload_bytes ...
//   const Message m = decode_payload(h, payload);              // throws: kMalformedMessage
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "protocol/messages.h"

namespace strielad::protocol {

struct FrameHeader {
  std::uint32_t payload_bytes = 0;
  MessageType type = MessageType::kHello;
  std::uint16_t flags = 0;  // 0, or kFrameFlagSlices on a NodeResult
  friend bool operator==(const FrameHeader&, const FrameHeader&) = default;
};

// The frame (header and payload) of `message`. Throws kInvalidArgument, naming the
// message type and field, for a message a peer would reject: a string or list over
// its limit, invalid UTF-8, a non-finite priority, a node listed twice in one
// CutUpdate, an unknown WireError or NodeOutcome, an unencodable mesh
// (protocol/mesh_encoding.h) or a kMesh result without triangles, triangles for
// another outcome, a NodeResult slice list over kMaxSliceResults or with a slice
// mesh that is not MeshRole::kSlice, a payload over kMaxClientPayloadBytes (client messages) or
// kMaxServerPayloadBytes (server messages), and so on.
std::vector<std::byte> encode_frame(const Message& message);

// The payload length field of a frame header, unchecked: for telling an oversized frame
// (kTooLarge) from a malformed one. Reads the first kFrameHeaderBytes bytes of
// `header`; throws kTruncated when there are fewer.
std::uint32_t peek_payload_length(std::span<const std::byte> header);

// Reads and checks the first kFrameHeaderBytes bytes of `header`. Throws kTruncated
// when there are fewer, kInvalidInput for a payload length above `max_payload_bytes`,
// an unknown message type or flags other than 0 (kFrameFlagSlices on a NodeResult
// excepted). Does not look at the payload.
FrameHeader decode_frame_header(std::span<const std::byte> header,
                                std::uint32_t max_payload_bytes);

// Decodes a payload of `header.type`. `payload` must hold exactly header.payload_bytes
// bytes: fewer is kTruncated, more is kInvalidArgument. Throws kTruncated or
// kInvalidInput (above) for a payload formats/protocol.md rejects, trailing bytes after
// the last field included; checks every count and length against the bytes that
// remain before allocating for it.
Message decode_payload(const FrameHeader& header, std::span<const std::byte> payload);

// decode_frame_header + decode_payload of one whole frame. Throws kTruncated when the
// frame is shorter than its header announces, kInvalidInput when bytes follow the
// payload.
Message decode_frame(std::span<const std::byte> frame, std::uint32_t max_payload_bytes);

}  // namespace strielad::protocol
