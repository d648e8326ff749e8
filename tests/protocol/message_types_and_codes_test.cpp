// SPDX-License-Identifier: Apache-2.0
// Message types, their names and direction, and the wire numbers of errors
// (formats/protocol.md, "Connection and frames" and "Error codes").
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "protocol/messages.h"

namespace strielad::protocol {
namespace {

TEST(MessageTypesAndCodesTest, EveryAlternativeHasItsTypeNameAndDirection) {
  const std::vector<std::pair<Message, std::string_view>> cases = {
      {Hello{}, "Hello"},         {OpenDataset{}, "OpenDataset"},
      {SetScene{}, "SetScene"},   {SetTime{}, "SetTime"},
      {CutUpdate{}, "CutUpdate"}, {StatsRequest{}, "StatsRequest"},
      {Goodbye{}, "Goodbye"},     {Welcome{}, "Welcome"},
      {DatasetOpened{}, "DatasetOpened"}, {GenerationStarted{}, "GenerationStarted"},
      {NodeResult{}, "NodeResult"}, {NodeFailed{}, "NodeFailed"},
      {ErrorMessage{}, "Error"},  {Stats{}, "Stats"},
  };
  ASSERT_EQ(cases.size(), std::variant_size_v<Message>);
  std::set<MessageType> types;
  for (const auto& [message, name] : cases) {
    const MessageType type = message_type(message);
    types.insert(type);
    EXPECT_EQ(message_type_name(type), name);
    const auto value = static_cast<std::uint16_t>(type);
    EXPECT_EQ(is_client_message(type), value <= 7) << name;
    EXPECT_TRUE((value >= 1 && value <= 7) || (value >= 101 && value <= 107)) << name;
  }
  EXPECT_EQ(types.size(), cases.size());
}

TEST(MessageTypesAndCodesTest, ValuesOutsideTheTableAreUnknown) {
  for (const std::uint16_t v : {0, 8, 100, 108, 0xFFFF}) {
    EXPECT_EQ(message_type_name(static_cast<MessageType>(v)), "unknown");
    EXPECT_FALSE(is_client_message(static_cast<MessageType>(v)));
  }
}

TEST(MessageTypesAndCodesTest, LibraryErrorCodesKeepTheirMeaningOnTheWire) {
  const ErrorCode codes[] = {ErrorCode::kInvalidArgument, ErrorCode::kNotFound,
                             ErrorCode::kInvalidInput,    ErrorCode::kUnsupported,
                             ErrorCode::kCorrupt,         ErrorCode::kTruncated,
                             ErrorCode::kVersionTooNew,   ErrorCode::kIo,
                             ErrorCode::kAlreadyExists,   ErrorCode::kCancelled,
                             ErrorCode::kInternal};
  std::uint16_t expected = 1;
  for (const ErrorCode code : codes) {
    const WireError wire = wire_error(code);
    EXPECT_EQ(static_cast<std::uint16_t>(wire), expected++) << error_code_name(code);
    EXPECT_EQ(error_code(wire), code);
    EXPECT_EQ(wire_error_name(wire), error_code_name(code));
  }
}

TEST(MessageTypesAndCodesTest, ProtocolErrorCodesHaveNamesAndMapToInvalidInput) {
  const std::pair<WireError, std::string_view> codes[] = {
      {WireError::kMalformedMessage, "malformed message"}, {WireError::kTooLarge, "too large"},
      {WireError::kUnauthorized, "unauthorized"},   {WireError::kVersionMismatch, "version mismatch"},
      {WireError::kOutOfOrder, "out of order"},     {WireError::kServerBusy, "server busy"},
      {WireError::kShuttingDown, "shutting down"}};
  for (const auto& [code, name] : codes) {
    EXPECT_EQ(wire_error_name(code), name);
    EXPECT_EQ(error_code(code), ErrorCode::kInvalidInput);
  }
}

TEST(MessageTypesAndCodesTest, ExactlyTheTabledErrorNumbersAreKnown) {
  int known = 0;
  for (std::uint32_t v = 0; v <= 0xFFFF; ++v) {
    const bool listed = (v >= 1 && v <= 11) || (v >= 100 && v <= 106);
    EXPECT_EQ(is_wire_error(static_cast<std::uint16_t>(v)), listed) << v;
    known += listed;
  }
  EXPECT_EQ(known, 18);
  EXPECT_EQ(wire_error_name(static_cast<WireError>(12)), "unknown");
}

}  // namespace
}  // namespace strielad::protocol
