// SPDX-License-Identifier: Apache-2.0
// The client/server protocol's messages as values (formats/protocol.md). One struct per
// message type; `Message` is their sum. Encoding and decoding live in
// protocol/message_codec.h, the compact mesh encoding in protocol/mesh_encoding.h.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/error.h"
#include "extract/mesh.h"
#include "extract/node_extraction.h"
#include "octree/octree_layout.h"

namespace strielad::protocol {

// Highest version of formats/protocol.md this library speaks (it speaks 1 ..= this).
inline constexpr std::uint16_t kProtocolVersion = 2;
// The first version whose NodeResult may carry slice results.
inline constexpr std::uint16_t kProtocolVersionSlices = 2;
// Every Hello starts with these 8 bytes.
inline constexpr std::array<char, 8> kHelloMagic{'S', 'T', 'R', 'I', 'E', 'L', 'A', 'D'};

// Frame header: u32 payload length, u16 message type, u16 flags. 8 bytes.
inline constexpr std::size_t kFrameHeaderBytes = 8;
// Frame flag (version 2): on a NodeResult, a list of slice results follows the
// sub-volume results. The only flag; every other bit, and this one on any other
// message type, must be 0.
inline constexpr std::uint16_t kFrameFlagSlices = 0x0001;

// Fixed protocol limits (formats/protocol.md, "Limits"). A server may announce lower
// values in Welcome; a peer rejects anything above these whatever was announced.
inline constexpr std::uint32_t kMaxClientPayloadBytes = 2u << 20;    // client -> server
inline constexpr std::uint32_t kMaxServerPayloadBytes = 256u << 20;  // server -> client
inline constexpr std::uint32_t kMaxNodesPerUpdate = 1u << 18;  // entries of one CutUpdate list
inline constexpr std::size_t kMaxNameBytes = 1024;             // dataset names, server names
inline constexpr std::size_t kMaxTokenBytes = 4096;
inline constexpr std::size_t kMaxMessageTextBytes = 4096;      // error messages and reasons
inline constexpr std::uint32_t kMaxSliceResults = 16;          // a scene's slices

enum class MessageType : std::uint16_t {
  // client -> server
  kHello = 1,
  kOpenDataset = 2,
  kSetScene = 3,
  kSetTime = 4,
  kCutUpdate = 5,
  kStatsRequest = 6,
  kGoodbye = 7,
  // server -> client
  kWelcome = 101,
  kDatasetOpened = 102,
  kGenerationStarted = 103,
  kNodeResult = 104,
  kNodeFailed = 105,
  kError = 106,
  kStats = 107,
};

// Stable wire numbers of errors (formats/protocol.md, "Error codes"): library
// ErrorCodes keep their meaning, protocol-level failures get their own.
enum class WireError : std::uint16_t {
  kInvalidArgument = 1,
  kNotFound = 2,
  kInvalidInput = 3,
  kUnsupported = 4,
  kCorrupt = 5,
  kTruncated = 6,
  kVersionTooNew = 7,
  kIo = 8,
  kAlreadyExists = 9,
  kCancelled = 10,
  kInternal = 11,
  kMalformedMessage = 100,  // a frame or payload that formats/protocol.md rejects
  kTooLarge = 101,          // a frame, list or text above a limit
  kUnauthorized = 102,      // wrong or missing token
  kVersionMismatch = 103,   // no common protocol version
  kOutOfOrder = 104,        // e.g. CutUpdate before a dataset and scene
  kServerBusy = 105,        // client limit reached
  kShuttingDown = 106,
};

struct NodePriority {
  NodeId node = 0;
  float priority = 0;  // smaller = sooner (the paper's camera distance); finite
  friend bool operator==(const NodePriority&, const NodePriority&) = default;
};

// client -> server -----------------------------------------------------------------

struct Hello {
  std::uint16_t version = kProtocolVersion;  // highest version the client speaks
  std::string client_name;                   // free text for logs
  std::string token;                         // shared secret, empty when none
  friend bool operator==(const Hello&, const Hello&) = default;
};

// Opens a store found under the server's root by its relative name ("paper/step-one").
struct OpenDataset {
  std::string name;
  friend bool operator==(const OpenDataset&, const OpenDataset&) = default;
};

// Sets the scene (formats/scene.md JSON, its "time" included) and starts `generation`.
struct SetScene {
  std::uint32_t generation = 0;  // strictly greater than every earlier generation
  std::string scene_json;
  friend bool operator==(const SetScene&, const SetScene&) = default;
};

// Keeps the scene, changes its time step, starts `generation`.
struct SetTime {
  std::uint32_t generation = 0;
  std::uint32_t step = 0;
  friend bool operator==(const SetTime&, const SetTime&) = default;
};

// Differences of the client's cut since its last update, for the current generation
// (a new generation starts with an empty cut).
struct CutUpdate {
  std::uint32_t generation = 0;
  std::vector<NodePriority> added;
  std::vector<NodeId> removed;
  std::vector<NodePriority> reprioritized;
  friend bool operator==(const CutUpdate&, const CutUpdate&) = default;
};

struct StatsRequest {
  friend bool operator==(const StatsRequest&, const StatsRequest&) = default;
};

struct Goodbye {
  friend bool operator==(const Goodbye&, const Goodbye&) = default;
};

// server -> client -----------------------------------------------------------------

struct ServerLimits {
  std::uint32_t max_payload_bytes = kMaxClientPayloadBytes;  // client -> server frames
  std::uint32_t max_nodes_per_update = kMaxNodesPerUpdate;
  std::uint32_t max_subvolumes = 64;
  std::uint32_t max_limits_per_subvolume = 16;
  friend bool operator==(const ServerLimits&, const ServerLimits&) = default;
};

struct Welcome {
  std::uint16_t version = kProtocolVersion;  // version both will speak
  std::string server_name;
  ServerLimits limits;
  friend bool operator==(const Welcome&, const Welcome&) = default;
};

// The store's MANIFEST file bytes as on disk (formats/store.md), from which the client
// knows axes, variables, time steps and the octree.
struct DatasetOpened {
  std::string name;
  std::vector<std::byte> manifest;
  friend bool operator==(const DatasetOpened&, const DatasetOpened&) = default;
};

// Acknowledges SetScene / SetTime: from here on only results of `generation` follow.
struct GenerationStarted {
  std::uint32_t generation = 0;
  std::uint32_t step = 0;
  std::string scene_json;  // the canonical scene (formats/scene.md) now in effect
  friend bool operator==(const GenerationStarted&, const GenerationStarted&) = default;
};

// One node's results: the extraction's own SubVolumeResult and SliceResult
// (extract/node_extraction.h), of which the wire carries the id, outcome, reason and
// mesh (a decoded SubVolumeResult has default `stats`). `mesh` is set (non-empty) only
// for kMesh; it arrives quantized (protocol/mesh_encoding.h), so positions are within
// the quantum of the server's, and without attribute names (the client knows them from
// the scene). A slice's mesh has face kind 4 (FaceKind::kSlice) on every triangle and
// one attribute, the slice's colouring variable; mesh.subvolume_id is the slice id.
struct NodeResult {
  std::uint32_t generation = 0;
  NodeId node = 0;
  std::vector<SubVolumeResult> subvolumes;  // in scene order
  // In the scene's slice order; only on a connection of version 2 or later (the frame
  // then has kFrameFlagSlices). Empty: no slice list on the wire.
  std::vector<SliceResult> slices{};
  friend bool operator==(const NodeResult&, const NodeResult&) = default;
};

struct NodeFailed {
  std::uint32_t generation = 0;
  NodeId node = 0;
  WireError code = WireError::kInternal;
  std::string message;
  friend bool operator==(const NodeFailed&, const NodeFailed&) = default;
};

// A request-level error. When `fatal`, the server closes the connection after it.
struct ErrorMessage {
  WireError code = WireError::kInternal;
  bool fatal = false;
  std::string message;
  friend bool operator==(const ErrorMessage&, const ErrorMessage&) = default;
};

// Server statistics as one JSON object (formats/protocol.md, "Statistics").
struct Stats {
  std::string json;
  friend bool operator==(const Stats&, const Stats&) = default;
};

using Message = std::variant<Hello, OpenDataset, SetScene, SetTime, CutUpdate, StatsRequest,
                             Goodbye, Welcome, DatasetOpened, GenerationStarted, NodeResult,
                             NodeFailed, ErrorMessage, Stats>;

MessageType message_type(const Message& message);
// "Hello", "CutUpdate", ... ("Error" for kError); "unknown" for a value not listed above.
std::string_view message_type_name(MessageType type);
// Whether a client sends this type (Hello .. Goodbye); false for server types and for
// values not listed above.
bool is_client_message(MessageType type);

// Wire numbers for library errors and back.
WireError wire_error(ErrorCode code);
ErrorCode error_code(WireError code);  // protocol-level codes map to kInvalidInput
std::string_view wire_error_name(WireError code);  // "malformed message"; "unknown" if unlisted
// Whether `value` is one of the WireError numbers listed above.
bool is_wire_error(std::uint16_t value);

}  // namespace strielad::protocol
