// SPDX-License-Identifier: Apache-2.0
#include "protocol/messages.h"

#include <array>
#include <type_traits>
#include <variant>

namespace strielad::protocol {

namespace {

// MessageType of each alternative of `Message`, in the variant's order.
constexpr std::array kTypeOfAlternative{
    MessageType::kHello,         MessageType::kOpenDataset,   MessageType::kSetScene,
    MessageType::kSetTime,       MessageType::kCutUpdate,     MessageType::kStatsRequest,
    MessageType::kGoodbye,       MessageType::kWelcome,       MessageType::kDatasetOpened,
    MessageType::kGenerationStarted, MessageType::kNodeResult, MessageType::kNodeFailed,
    MessageType::kError,         MessageType::kStats,
};
static_assert(kTypeOfAlternative.size() == std::variant_size_v<Message>);
static_assert(std::is_same_v<std::variant_alternative_t<4, Message>, CutUpdate>);
static_assert(std::is_same_v<std::variant_alternative_t<12, Message>, ErrorMessage>);

}  // namespace

MessageType message_type(const Message& message) { return kTypeOfAlternative[message.index()]; }

std::string_view message_type_name(MessageType type) {
  switch (type) {
    case MessageType::kHello: return "Hello";
    case MessageType::kOpenDataset: return "OpenDataset";
    case MessageType::kSetScene: return "SetScene";
    case MessageType::kSetTime: return "SetTime";
    case MessageType::kCutUpdate: return "CutUpdate";
    case MessageType::kStatsRequest: return "StatsRequest";
    case MessageType::kGoodbye: return "Goodbye";
    case MessageType::kWelcome: return "Welcome";
    case MessageType::kDatasetOpened: return "DatasetOpened";
    case MessageType::kGenerationStarted: return "GenerationStarted";
    case MessageType::kNodeResult: return "NodeResult";
    case MessageType::kNodeFailed: return "NodeFailed";
    case MessageType::kError: return "Error";
    case MessageType::kStats: return "Stats";
  }
  return "unknown";
}

bool is_client_message(MessageType type) {
  const auto v = static_cast<std::uint16_t>(type);
  return v >= static_cast<std::uint16_t>(MessageType::kHello) &&
         v <= static_cast<std::uint16_t>(MessageType::kGoodbye);
}

WireError wire_error(ErrorCode code) {
  switch (code) {
    case ErrorCode::kInvalidArgument: return WireError::kInvalidArgument;
    case ErrorCode::kNotFound: return WireError::kNotFound;
    case ErrorCode::kInvalidInput: return WireError::kInvalidInput;
    case ErrorCode::kUnsupported: return WireError::kUnsupported;
    case ErrorCode::kCorrupt: return WireError::kCorrupt;
    case ErrorCode::kTruncated: return WireError::kTruncated;
    case ErrorCode::kVersionTooNew: return WireError::kVersionTooNew;
    case ErrorCode::kIo: return WireError::kIo;
    case ErrorCode::kAlreadyExists: return WireError::kAlreadyExists;
    case ErrorCode::kCancelled: return WireError::kCancelled;
    case ErrorCode::kInternal: return WireError::kInternal;
  }
  return WireError::kInternal;
}

ErrorCode error_code(WireError code) {
  switch (code) {
    case WireError::kInvalidArgument: return ErrorCode::kInvalidArgument;
    case WireError::kNotFound: return ErrorCode::kNotFound;
    case WireError::kInvalidInput: return ErrorCode::kInvalidInput;
    case WireError::kUnsupported: return ErrorCode::kUnsupported;
    case WireError::kCorrupt: return ErrorCode::kCorrupt;
    case WireError::kTruncated: return ErrorCode::kTruncated;
    case WireError::kVersionTooNew: return ErrorCode::kVersionTooNew;
    case WireError::kIo: return ErrorCode::kIo;
    case WireError::kAlreadyExists: return ErrorCode::kAlreadyExists;
    case WireError::kCancelled: return ErrorCode::kCancelled;
    case WireError::kInternal: return ErrorCode::kInternal;
    case WireError::kMalformedMessage:
    case WireError::kTooLarge:
    case WireError::kUnauthorized:
    case WireError::kVersionMismatch:
    case WireError::kOutOfOrder:
    case WireError::kServerBusy:
    case WireError::kShuttingDown: return ErrorCode::kInvalidInput;
  }
  return ErrorCode::kInvalidInput;
}

std::string_view wire_error_name(WireError code) {
  switch (code) {
    case WireError::kMalformedMessage: return "malformed message";
    case WireError::kTooLarge: return "too large";
    case WireError::kUnauthorized: return "unauthorized";
    case WireError::kVersionMismatch: return "version mismatch";
    case WireError::kOutOfOrder: return "out of order";
    case WireError::kServerBusy: return "server busy";
    case WireError::kShuttingDown: return "shutting down";
    default: break;
  }
  return is_wire_error(static_cast<std::uint16_t>(code)) ? error_code_name(error_code(code))
                                                         : std::string_view("unknown");
}

bool is_wire_error(std::uint16_t value) {
  return (value >= static_cast<std::uint16_t>(WireError::kInvalidArgument) &&
          value <= static_cast<std::uint16_t>(WireError::kInternal)) ||
         (value >= static_cast<std::uint16_t>(WireError::kMalformedMessage) &&
          value <= static_cast<std::uint16_t>(WireError::kShuttingDown));
}

}  // namespace strielad::protocol
