// SPDX-License-Identifier: Apache-2.0
// Protocol messages (formats/protocol.md) over a socket: one frame at a time, the
// payload size checked against the receiver's limit before anything is allocated.
#pragma once

#include <cstdint>
#include <string>

#include "net/socket.h"
#include "protocol/messages.h"

namespace strielad::net {

struct ReceivedMessage {
  enum class Status { kMessage, kEndOfStream, kRejected };
  Status status = Status::kEndOfStream;
  protocol::Message message;
  // For kRejected: why (kTooLarge, kMalformedMessage) and a message naming the field.
  protocol::WireError error = protocol::WireError::kMalformedMessage;
  std::string reason;
  std::size_t frame_bytes = 0;  // header and payload, as received
};

// Reads one frame. kEndOfStream when the peer closed cleanly between frames; kRejected
// for a frame formats/protocol.md rejects (an oversized one is refused from its header,
// its payload is never read: the connection must then be closed).
// \error kIo when the connection fails or closes inside a frame.
ReceivedMessage read_message(const Socket& socket, std::uint32_t max_payload_bytes);
// The same, and \error kIo when `deadline` passes before the whole frame arrived.
ReceivedMessage read_message(const Socket& socket, std::uint32_t max_payload_bytes,
                             Deadline deadline);

// \error kIo when the peer is gone.
void write_message(const Socket& socket, const protocol::Message& message);

}  // namespace strielad::net
