// SPDX-License-Identifier: Apache-2.0
#include "net/message_stream.h"

#include <array>
#include <vector>

#include "core/error.h"
#include "protocol/message_codec.h"

namespace strielad::net {

namespace {

bool read_exact(const Socket& socket, std::span<std::byte> bytes, const Deadline* deadline) {
  return deadline ? socket.read_exact(bytes, *deadline) : socket.read_exact(bytes);
}

ReceivedMessage read_message_until(const Socket& socket, std::uint32_t max_payload_bytes,
                                   const Deadline* deadline) {
  ReceivedMessage out;
  std::array<std::byte, protocol::kFrameHeaderBytes> header_bytes{};
  if (!read_exact(socket, header_bytes, deadline)) return out;  // kEndOfStream
  out.status = ReceivedMessage::Status::kRejected;
  const std::uint32_t length = protocol::peek_payload_length(header_bytes);
  if (length > max_payload_bytes) {
    out.error = protocol::WireError::kTooLarge;
    out.reason = fmt::format("frame of {} payload bytes exceeds the limit of {}", length,
                             max_payload_bytes);
    return out;
  }
  protocol::FrameHeader header;
  try {
    header = protocol::decode_frame_header(header_bytes, max_payload_bytes);
  } catch (const Error& e) {
    out.reason = e.what();
    return out;
  }
  std::vector<std::byte> payload(header.payload_bytes);
  out.frame_bytes = protocol::kFrameHeaderBytes + payload.size();
  if (!payload.empty() && !read_exact(socket, payload, deadline)) {
    throw make_error(ErrorCode::kIo, "{}: connection closed inside a frame", socket.peer());
  }
  try {
    out.message = protocol::decode_payload(header, payload);
  } catch (const Error& e) {
    out.reason = e.what();
    return out;
  }
  out.status = ReceivedMessage::Status::kMessage;
  return out;
}

}  // namespace

ReceivedMessage read_message(const Socket& socket, std::uint32_t max_payload_bytes) {
  return read_message_until(socket, max_payload_bytes, nullptr);
}

ReceivedMessage read_message(const Socket& socket, std::uint32_t max_payload_bytes,
                             Deadline deadline) {
  return read_message_until(socket, max_payload_bytes, &deadline);
}

void write_message(const Socket& socket, const protocol::Message& message) {
  socket.write_all(protocol::encode_frame(message));
}

}  // namespace strielad::net
