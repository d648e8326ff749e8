// SPDX-License-Identifier: Apache-2.0
#include "protocol/message_codec.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>

#include "core/byte_io.h"
#include "protocol/mesh_encoding.h"
#include "scene/scene.h"

namespace strielad::protocol {

namespace {

constexpr std::size_t kNodePriorityBytes = 8;  // u32 node, f32 priority
constexpr std::size_t kMinSubVolumeBytes = 7;  // u32 id, u8 outcome, u16 reason length
constexpr NodeOutcome kLastOutcome = NodeOutcome::kSkippedNoData;

bool known_type(std::uint16_t v) {
  return message_type_name(static_cast<MessageType>(v)) != "unknown";
}

// Offset of the first byte that is not part of well-formed UTF-8 (RFC 3629: no
// overlong forms, no surrogates, nothing above U+10FFFF), or npos.
std::size_t invalid_utf8_at(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size()) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) {
      ++i;
      continue;
    }
    std::size_t length;
    std::uint32_t code_point, smallest;
    if ((c & 0xE0) == 0xC0) {
      length = 2, code_point = c & 0x1Fu, smallest = 0x80;
    } else if ((c & 0xF0) == 0xE0) {
      length = 3, code_point = c & 0x0Fu, smallest = 0x800;
    } else if ((c & 0xF8) == 0xF0) {
      length = 4, code_point = c & 0x07u, smallest = 0x10000;
    } else {
      return i;
    }
    if (s.size() - i < length) return i;
    for (std::size_t k = 1; k < length; ++k) {
      const auto cc = static_cast<unsigned char>(s[i + k]);
      if ((cc & 0xC0) != 0x80) return i;
      code_point = (code_point << 6) | (cc & 0x3Fu);
    }
    if (code_point < smallest || code_point > 0x10FFFF ||
        (code_point >= 0xD800 && code_point <= 0xDFFF)) {
      return i;
    }
    i += length;
  }
  return std::string_view::npos;
}

// --- rules shared by the encoder (kInvalidArgument) and the decoder (kInvalidInput) ---

struct Rules {
  ErrorCode code;
  std::string_view what;  // "CutUpdate" or "encode CutUpdate"

  template <typename... Args>
  Error fail(std::string_view field, fmt::format_string<Args...> format, Args&&... args) const {
    return Error(code, fmt::format("{}: {}: {}", what, field,
                                   fmt::format(format, std::forward<Args>(args)...)));
  }

  void text(std::string_view field, std::string_view s, std::size_t max_bytes) const {
    if (s.size() > max_bytes) {
      throw fail(field, "{} bytes, over the limit of {}", s.size(), max_bytes);
    }
    if (const std::size_t at = invalid_utf8_at(s); at != std::string_view::npos) {
      throw fail(field, "not valid UTF-8 at byte {}", at);
    }
  }

  void wire_error_code(std::string_view field, WireError code_value) const {
    const auto v = static_cast<std::uint16_t>(code_value);
    if (!is_wire_error(v)) throw fail(field, "{} is not an error code", v);
  }
};

void validate(const Hello& m, const Rules& r) {
  if (m.version == 0) throw r.fail("version", "0 (versions start at 1)");
  r.text("client_name", m.client_name, kMaxNameBytes);
  r.text("token", m.token, kMaxTokenBytes);
}

void validate(const OpenDataset& m, const Rules& r) { r.text("name", m.name, kMaxNameBytes); }

void validate(const SetScene& m, const Rules& r) {
  r.text("scene_json", m.scene_json, kMaxSceneBytes);
}

void validate(const SetTime&, const Rules&) {}
void validate(const StatsRequest&, const Rules&) {}
void validate(const Goodbye&, const Rules&) {}

void validate(const CutUpdate& m, const Rules& r) {
  using List = std::pair<std::string_view, std::size_t>;  // name, size
  const std::array<List, 3> lists{List{"added", m.added.size()},
                                  List{"removed", m.removed.size()},
                                  List{"reprioritized", m.reprioritized.size()}};
  for (const auto& [name, size] : lists) {
    if (size > kMaxNodesPerUpdate) {
      throw r.fail(name, "{} entries, over the limit of {}", size, kMaxNodesPerUpdate);
    }
  }
  const auto check_priorities = [&](std::string_view name, const std::vector<NodePriority>& l) {
    for (std::size_t i = 0; i < l.size(); ++i) {
      if (!std::isfinite(l[i].priority)) {
        throw r.fail(fmt::format("{}[{}].priority", name, i), "not finite");
      }
    }
  };
  check_priorities("added", m.added);
  check_priorities("reprioritized", m.reprioritized);

  // A node appears at most once in one update: sort (node, list, index) and compare
  // neighbours, naming the later entry and the earlier one.
  std::vector<std::uint64_t> keys;
  keys.reserve(m.added.size() + m.removed.size() + m.reprioritized.size());
  const auto key = [](NodeId node, std::uint64_t list, std::uint64_t index) {
    return std::uint64_t{node} << 32 | list << 24 | index;
  };
  for (std::size_t i = 0; i < m.added.size(); ++i) keys.push_back(key(m.added[i].node, 0, i));
  for (std::size_t i = 0; i < m.removed.size(); ++i) keys.push_back(key(m.removed[i], 1, i));
  for (std::size_t i = 0; i < m.reprioritized.size(); ++i) {
    keys.push_back(key(m.reprioritized[i].node, 2, i));
  }
  std::sort(keys.begin(), keys.end());
  const auto at = std::adjacent_find(keys.begin(), keys.end(), [](std::uint64_t a, std::uint64_t b) {
    return a >> 32 == b >> 32;
  });
  if (at != keys.end()) {
    const auto place = [&](std::uint64_t k) {
      return fmt::format("{}[{}]", lists[(k >> 24) & 0xFF].first, k & 0xFFFFFF);
    };
    throw r.fail(place(at[1]) + ".node", "node {} is also listed at {}", *at >> 32, place(at[0]));
  }
}

void validate(const Welcome& m, const Rules& r) {
  if (m.version == 0 || m.version > kProtocolVersion) {
    throw r.fail("version", "{} (this library speaks 1 ..= {})", m.version, kProtocolVersion);
  }
  r.text("server_name", m.server_name, kMaxNameBytes);
  const auto limit = [&](std::string_view field, std::uint64_t value, std::uint64_t max) {
    if (value == 0 || value > max) {
      throw r.fail(fmt::format("limits.{}", field), "{} is outside 1 ..= {}", value, max);
    }
  };
  limit("max_payload_bytes", m.limits.max_payload_bytes, kMaxClientPayloadBytes);
  limit("max_nodes_per_update", m.limits.max_nodes_per_update, kMaxNodesPerUpdate);
  limit("max_subvolumes", m.limits.max_subvolumes, kMaxSubVolumes);
  limit("max_limits_per_subvolume", m.limits.max_limits_per_subvolume, kMaxLimitsPerSubVolume);
}

void validate(const DatasetOpened& m, const Rules& r) {
  r.text("name", m.name, kMaxNameBytes);
  if (m.manifest.size() > kMaxServerPayloadBytes) {
    throw r.fail("manifest", "{} bytes, over the limit of {}", m.manifest.size(),
                 kMaxServerPayloadBytes);
  }
}

void validate(const GenerationStarted& m, const Rules& r) {
  r.text("scene_json", m.scene_json, kMaxSceneBytes);
}

// One list of a NodeResult (its sub-volume or slice results): at most `max_entries`,
// ids in 1 ..= max_id and distinct, known outcomes, reasons within the text limit, and
// triangles only with outcome kMesh. `id_of` gives an entry's id, `id_name` its field.
template <typename Result, typename IdOf>
void validate_results(const std::vector<Result>& results, std::string_view list,
                      std::size_t max_entries, std::uint32_t max_id, std::string_view id_name,
                      IdOf id_of, const Rules& r) {
  if (results.size() > max_entries) {
    throw r.fail(std::string(list), "{} entries, over the limit of {}", results.size(),
                 max_entries);
  }
  for (std::size_t i = 0; i < results.size(); ++i) {
    const Result& s = results[i];
    const std::string field = fmt::format("{}[{}]", list, i);
    const std::string id_field = fmt::format("{}.{}", field, id_name);
    if (id_of(s) == 0 || id_of(s) > max_id) {
      throw r.fail(id_field, "{} is outside 1 ..= {}", id_of(s), max_id);
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (id_of(results[j]) == id_of(s)) {
        throw r.fail(id_field, "{} is also at {}[{}]", id_of(s), list, j);
      }
    }
    if (s.outcome > kLastOutcome) {
      throw r.fail(field + ".outcome", "{} is not an outcome (0..4)",
                   static_cast<unsigned>(s.outcome));
    }
    r.text(field + ".reason", s.reason, kMaxMessageTextBytes);
    if (s.outcome != NodeOutcome::kMesh && !s.mesh.triangles.empty()) {
      throw r.fail(field + ".mesh", "{} triangles with outcome {}", s.mesh.triangles.size(),
                   node_outcome_name(s.outcome));
    }
  }
}

// The mesh itself is checked by encode_mesh / decode_mesh.
void validate(const NodeResult& m, const Rules& r) {
  validate_results(m.subvolumes, "subvolumes", kMaxSubVolumes, kMaxSubVolumeId, "subvolume_id",
                   [](const SubVolumeResult& s) { return s.subvolume_id; }, r);
  validate_results(m.slices, "slices", kMaxSliceResults, kMaxSliceId, "slice_id",
                   [](const SliceResult& s) { return s.slice_id; }, r);
}

void validate(const NodeFailed& m, const Rules& r) {
  r.wire_error_code("code", m.code);
  r.text("message", m.message, kMaxMessageTextBytes);
}

void validate(const ErrorMessage& m, const Rules& r) {
  r.wire_error_code("code", m.code);
  r.text("message", m.message, kMaxMessageTextBytes);
}

void validate(const Stats& m, const Rules& r) {
  r.text("json", m.json, kMaxServerPayloadBytes);
}

// --- payload writers (the message is valid) ------------------------------------------

void put_str16(ByteWriter& w, std::string_view s) {
  w.u16(static_cast<std::uint16_t>(s.size()));
  w.text(s);
}

void put_str32(ByteWriter& w, std::string_view s) {
  w.u32(static_cast<std::uint32_t>(s.size()));
  w.text(s);
}

void put_priorities(ByteWriter& w, const std::vector<NodePriority>& list) {
  w.u32(static_cast<std::uint32_t>(list.size()));
  for (const NodePriority& e : list) {
    w.u32(e.node);
    w.f32(e.priority);
  }
}

void write(const Hello& m, ByteWriter& w, const Rules&) {
  w.text(std::string_view(kHelloMagic.data(), kHelloMagic.size()));
  w.u16(m.version);
  put_str16(w, m.client_name);
  put_str16(w, m.token);
}

void write(const OpenDataset& m, ByteWriter& w, const Rules&) { put_str16(w, m.name); }

void write(const SetScene& m, ByteWriter& w, const Rules&) {
  w.u32(m.generation);
  put_str32(w, m.scene_json);
}

void write(const SetTime& m, ByteWriter& w, const Rules&) {
  w.u32(m.generation);
  w.u32(m.step);
}

void write(const CutUpdate& m, ByteWriter& w, const Rules&) {
  w.u32(m.generation);
  put_priorities(w, m.added);
  w.u32(static_cast<std::uint32_t>(m.removed.size()));
  for (const NodeId node : m.removed) w.u32(node);
  put_priorities(w, m.reprioritized);
}

void write(const StatsRequest&, ByteWriter&, const Rules&) {}
void write(const Goodbye&, ByteWriter&, const Rules&) {}

void write(const Welcome& m, ByteWriter& w, const Rules&) {
  w.u16(m.version);
  w.u32(m.limits.max_payload_bytes);
  w.u32(m.limits.max_nodes_per_update);
  w.u32(m.limits.max_subvolumes);
  w.u32(m.limits.max_limits_per_subvolume);
  put_str16(w, m.server_name);
}

void write(const DatasetOpened& m, ByteWriter& w, const Rules&) {
  put_str16(w, m.name);
  w.u32(static_cast<std::uint32_t>(m.manifest.size()));
  w.bytes(m.manifest);
}

void write(const GenerationStarted& m, ByteWriter& w, const Rules&) {
  w.u32(m.generation);
  w.u32(m.step);
  put_str32(w, m.scene_json);
}

void write(const NodeResult& m, ByteWriter& w, const Rules& r) {
  w.u32(m.generation);
  w.u32(m.node);
  w.u32(static_cast<std::uint32_t>(m.subvolumes.size()));
  for (std::size_t i = 0; i < m.subvolumes.size(); ++i) {
    const SubVolumeResult& s = m.subvolumes[i];
    w.u32(s.subvolume_id);
    w.u8(static_cast<std::uint8_t>(s.outcome));
    put_str16(w, s.reason);
    if (s.outcome == NodeOutcome::kMesh) {
      encode_mesh(s.mesh, w, fmt::format("{}: subvolumes[{}].mesh", r.what, i));
    }
  }
  if (m.slices.empty()) return;  // no slice list, no flag: a version-1 payload
  w.u32(static_cast<std::uint32_t>(m.slices.size()));
  for (std::size_t i = 0; i < m.slices.size(); ++i) {
    const SliceResult& s = m.slices[i];
    w.u32(s.slice_id);
    w.u8(static_cast<std::uint8_t>(s.outcome));
    put_str16(w, s.reason);
    if (s.outcome == NodeOutcome::kMesh) {
      encode_mesh(s.mesh, w, fmt::format("{}: slices[{}].mesh", r.what, i), MeshRole::kSlice);
    }
  }
}

void write(const NodeFailed& m, ByteWriter& w, const Rules&) {
  w.u32(m.generation);
  w.u32(m.node);
  w.u16(static_cast<std::uint16_t>(m.code));
  put_str16(w, m.message);
}

void write(const ErrorMessage& m, ByteWriter& w, const Rules&) {
  w.u16(static_cast<std::uint16_t>(m.code));
  w.u8(m.fatal ? 1 : 0);
  put_str16(w, m.message);
}

void write(const Stats& m, ByteWriter& w, const Rules&) { put_str32(w, m.json); }

// --- payload readers ---------------------------------------------------------------

// A ByteReader over one payload whose errors start with the message type's name, with
// the structural checks that must come before reading: lengths and counts against
// their limits and against the bytes that remain.
class PayloadReader {
 public:
  PayloadReader(std::span<const std::byte> payload, MessageType type)
      : name_(message_type_name(type)), in_(payload, name_), rules_{ErrorCode::kInvalidInput, name_} {}

  ByteReader& in() { return in_; }
  const Rules& rules() const { return rules_; }

  std::string str16(std::string_view field, std::size_t max_bytes) {
    return text(field, in_.u16(field), max_bytes);
  }
  std::string str32(std::string_view field, std::size_t max_bytes) {
    return text(field, in_.u32(field), max_bytes);
  }

  // A u32 entry count, at most `max`, whose entries of at least `entry_bytes` each fit
  // in the bytes that remain.
  std::uint32_t count(std::string_view field, std::size_t max, std::size_t entry_bytes) {
    const std::uint32_t n = in_.u32(field);
    if (n > max) throw rules_.fail(field, "{} entries, over the limit of {}", n, max);
    if (std::uint64_t{n} * entry_bytes > in_.remaining()) {
      throw make_error(ErrorCode::kTruncated, "{}: {}: {} entries need {} bytes, only {} remain",
                       name_, field, n, std::uint64_t{n} * entry_bytes, in_.remaining());
    }
    return n;
  }

  std::vector<NodePriority> priorities(std::string_view field) {
    std::vector<NodePriority> list(count(field, kMaxNodesPerUpdate, kNodePriorityBytes));
    for (NodePriority& e : list) {
      e.node = in_.u32(field);
      e.priority = in_.f32(field);
    }
    return list;
  }

  void finish() {
    if (in_.remaining() != 0) {
      throw make_error(ErrorCode::kInvalidInput, "{}: {} bytes after the last field", name_,
                       in_.remaining());
    }
  }

 private:
  std::string text(std::string_view field, std::size_t length, std::size_t max_bytes) {
    if (length > max_bytes) {
      throw rules_.fail(field, "{} bytes, over the limit of {}", length, max_bytes);
    }
    const auto b = in_.bytes(length, field);
    return std::string(reinterpret_cast<const char*>(b.data()), b.size());
  }

  std::string_view name_;
  ByteReader in_;
  Rules rules_;
};

Hello read_hello(PayloadReader& p) {
  const auto magic = p.in().bytes(kHelloMagic.size(), "magic");
  if (std::memcmp(magic.data(), kHelloMagic.data(), kHelloMagic.size()) != 0) {
    std::string hex;
    for (const std::byte b : magic) hex += fmt::format("{:02x}", static_cast<unsigned>(b));
    throw p.rules().fail("magic", "{} is not \"STRIELAD\"", hex);
  }
  Hello m;
  m.version = p.in().u16("version");
  m.client_name = p.str16("client_name", kMaxNameBytes);
  m.token = p.str16("token", kMaxTokenBytes);
  return m;
}

OpenDataset read_open_dataset(PayloadReader& p) { return {p.str16("name", kMaxNameBytes)}; }

SetScene read_set_scene(PayloadReader& p) {
  SetScene m;
  m.generation = p.in().u32("generation");
  m.scene_json = p.str32("scene_json", kMaxSceneBytes);
  return m;
}

SetTime read_set_time(PayloadReader& p) {
  SetTime m;
  m.generation = p.in().u32("generation");
  m.step = p.in().u32("step");
  return m;
}

CutUpdate read_cut_update(PayloadReader& p) {
  CutUpdate m;
  m.generation = p.in().u32("generation");
  m.added = p.priorities("added");
  m.removed.resize(p.count("removed", kMaxNodesPerUpdate, sizeof(NodeId)));
  for (NodeId& node : m.removed) node = p.in().u32("removed");
  m.reprioritized = p.priorities("reprioritized");
  return m;
}

Welcome read_welcome(PayloadReader& p) {
  Welcome m;
  m.version = p.in().u16("version");
  m.limits.max_payload_bytes = p.in().u32("limits.max_payload_bytes");
  m.limits.max_nodes_per_update = p.in().u32("limits.max_nodes_per_update");
  m.limits.max_subvolumes = p.in().u32("limits.max_subvolumes");
  m.limits.max_limits_per_subvolume = p.in().u32("limits.max_limits_per_subvolume");
  m.server_name = p.str16("server_name", kMaxNameBytes);
  return m;
}

DatasetOpened read_dataset_opened(PayloadReader& p) {
  DatasetOpened m;
  m.name = p.str16("name", kMaxNameBytes);
  const std::uint32_t n = p.in().u32("manifest");
  const auto bytes = p.in().bytes(n, "manifest");
  m.manifest.assign(bytes.begin(), bytes.end());
  return m;
}

GenerationStarted read_generation_started(PayloadReader& p) {
  GenerationStarted m;
  m.generation = p.in().u32("generation");
  m.step = p.in().u32("step");
  m.scene_json = p.str32("scene_json", kMaxSceneBytes);
  return m;
}

// One entry of a NodeResult list (a sub-volume or a slice result): id, outcome, reason
// and, for outcome kMesh, the mesh decoded in `role`, carrying the entry's id.
template <typename Result>
void read_result(PayloadReader& p, const std::string& field, std::string_view id_name,
                 MeshRole role, std::uint32_t& id, Result& s) {
  id = p.in().u32(fmt::format("{}.{}", field, id_name));
  const std::uint8_t outcome = p.in().u8(field + ".outcome");
  if (outcome > static_cast<std::uint8_t>(kLastOutcome)) {
    throw p.rules().fail(field + ".outcome", "{} is not an outcome (0..4)", outcome);
  }
  s.outcome = static_cast<NodeOutcome>(outcome);
  s.reason = p.str16(field + ".reason", kMaxMessageTextBytes);
  if (s.outcome == NodeOutcome::kMesh) {
    s.mesh = decode_mesh(p.in(), fmt::format("{}: {}.mesh", p.rules().what, field), role);
    s.mesh.subvolume_id = id;
  }
}

NodeResult read_node_result(PayloadReader& p, std::uint16_t flags) {
  NodeResult m;
  m.generation = p.in().u32("generation");
  m.node = p.in().u32("node");
  m.subvolumes.resize(p.count("subvolumes", kMaxSubVolumes, kMinSubVolumeBytes));
  for (std::size_t i = 0; i < m.subvolumes.size(); ++i) {
    SubVolumeResult& s = m.subvolumes[i];
    read_result(p, fmt::format("subvolumes[{}]", i), "subvolume_id", MeshRole::kSubVolume,
                s.subvolume_id, s);
  }
  if ((flags & kFrameFlagSlices) == 0) return m;
  const std::uint32_t slices = p.count("slices", kMaxSliceResults, kMinSubVolumeBytes);
  if (slices == 0) {
    throw p.rules().fail("slices", "0 entries with the slices flag set (at least 1)");
  }
  m.slices.resize(slices);
  for (std::size_t i = 0; i < m.slices.size(); ++i) {
    SliceResult& s = m.slices[i];
    read_result(p, fmt::format("slices[{}]", i), "slice_id", MeshRole::kSlice, s.slice_id, s);
  }
  return m;
}

NodeFailed read_node_failed(PayloadReader& p) {
  NodeFailed m;
  m.generation = p.in().u32("generation");
  m.node = p.in().u32("node");
  m.code = static_cast<WireError>(p.in().u16("code"));
  m.message = p.str16("message", kMaxMessageTextBytes);
  return m;
}

ErrorMessage read_error(PayloadReader& p) {
  ErrorMessage m;
  m.code = static_cast<WireError>(p.in().u16("code"));
  const std::uint8_t fatal = p.in().u8("fatal");
  if (fatal > 1) throw p.rules().fail("fatal", "{} (must be 0 or 1)", fatal);
  m.fatal = fatal == 1;
  m.message = p.str16("message", kMaxMessageTextBytes);
  return m;
}

Stats read_stats(PayloadReader& p) { return {p.str32("json", kMaxServerPayloadBytes)}; }

Message read_payload(PayloadReader& p, MessageType type, std::uint16_t flags) {
  switch (type) {
    case MessageType::kHello: return read_hello(p);
    case MessageType::kOpenDataset: return read_open_dataset(p);
    case MessageType::kSetScene: return read_set_scene(p);
    case MessageType::kSetTime: return read_set_time(p);
    case MessageType::kCutUpdate: return read_cut_update(p);
    case MessageType::kStatsRequest: return StatsRequest{};
    case MessageType::kGoodbye: return Goodbye{};
    case MessageType::kWelcome: return read_welcome(p);
    case MessageType::kDatasetOpened: return read_dataset_opened(p);
    case MessageType::kGenerationStarted: return read_generation_started(p);
    case MessageType::kNodeResult: return read_node_result(p, flags);
    case MessageType::kNodeFailed: return read_node_failed(p);
    case MessageType::kError: return read_error(p);
    case MessageType::kStats: return read_stats(p);
  }
  throw make_error(ErrorCode::kInvalidInput, "unknown message type {}",
                   static_cast<unsigned>(type));
}

// The whole header or nothing.
void require_header(std::span<const std::byte> header) {
  if (header.size() < kFrameHeaderBytes) {
    throw make_error(ErrorCode::kTruncated, "frame header: needs {} bytes, only {} remain",
                     kFrameHeaderBytes, header.size());
  }
}

}  // namespace

std::vector<std::byte> encode_frame(const Message& message) {
  const MessageType type = message_type(message);
  const std::string what = fmt::format("encode {}", message_type_name(type));
  const Rules rules{ErrorCode::kInvalidArgument, what};
  ByteWriter out;
  out.zeros(kFrameHeaderBytes);
  std::visit(
      [&](const auto& m) {
        validate(m, rules);
        write(m, out, rules);
      },
      message);
  const std::size_t payload = out.size() - kFrameHeaderBytes;
  const std::uint32_t limit =
      is_client_message(type) ? kMaxClientPayloadBytes : kMaxServerPayloadBytes;
  if (payload > limit) {
    throw make_error(ErrorCode::kInvalidArgument, "{}: payload of {} bytes is over the limit of {}",
                     what, payload, limit);
  }
  std::vector<std::byte> frame = out.take();
  ByteWriter header;
  header.u32(static_cast<std::uint32_t>(payload));
  header.u16(static_cast<std::uint16_t>(type));
  const auto* result = std::get_if<NodeResult>(&message);
  header.u16(result != nullptr && !result->slices.empty() ? kFrameFlagSlices : 0);
  std::memcpy(frame.data(), header.data().data(), kFrameHeaderBytes);
  return frame;
}

std::uint32_t peek_payload_length(std::span<const std::byte> header) {
  require_header(header);
  return ByteReader(header, "frame header").u32("payload_length");
}

FrameHeader decode_frame_header(std::span<const std::byte> header,
                                std::uint32_t max_payload_bytes) {
  require_header(header);
  ByteReader in(header, "frame header");
  const std::uint32_t length = in.u32("payload_length");
  const std::uint16_t type = in.u16("type");
  const std::uint16_t flags = in.u16("flags");
  if (length > max_payload_bytes) {
    throw make_error(ErrorCode::kInvalidInput,
                     "frame header: payload_length: {} bytes, over the limit of {}", length,
                     max_payload_bytes);
  }
  if (!known_type(type)) {
    throw make_error(ErrorCode::kInvalidInput, "frame header: type: {} is not a message type",
                     type);
  }
  const auto message_type = static_cast<MessageType>(type);
  const std::uint16_t allowed = message_type == MessageType::kNodeResult ? kFrameFlagSlices : 0;
  if ((flags & ~allowed) != 0) {
    throw make_error(ErrorCode::kInvalidInput, "frame header: flags: {:#06x} (must be {})", flags,
                     allowed == 0 ? "0" : "0 or 0x0001 on a NodeResult");
  }
  return FrameHeader{length, message_type, flags};
}

Message decode_payload(const FrameHeader& header, std::span<const std::byte> payload) {
  const std::string_view name = message_type_name(header.type);
  if (name == "unknown") {
    throw make_error(ErrorCode::kInvalidInput, "frame header: type: {} is not a message type",
                     static_cast<unsigned>(header.type));
  }
  if (payload.size() < header.payload_bytes) {
    throw make_error(ErrorCode::kTruncated, "{}: payload has {} bytes, the header announces {}",
                     name, payload.size(), header.payload_bytes);
  }
  if (payload.size() > header.payload_bytes) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "{}: decode_payload got {} bytes for a payload of {}", name, payload.size(),
                     header.payload_bytes);
  }
  const std::uint16_t allowed = header.type == MessageType::kNodeResult ? kFrameFlagSlices : 0;
  if ((header.flags & ~allowed) != 0) {
    throw make_error(ErrorCode::kInvalidInput, "frame header: flags: {:#06x} are not allowed on {}",
                     header.flags, name);
  }
  PayloadReader reader(payload, header.type);
  Message message = read_payload(reader, header.type, header.flags);
  reader.finish();
  std::visit([&](const auto& m) { validate(m, reader.rules()); }, message);
  return message;
}

Message decode_frame(std::span<const std::byte> frame, std::uint32_t max_payload_bytes) {
  const FrameHeader header = decode_frame_header(frame, max_payload_bytes);
  const std::size_t available = frame.size() - kFrameHeaderBytes;
  if (available < header.payload_bytes) {
    throw make_error(ErrorCode::kTruncated,
                     "frame: the {} payload needs {} bytes, only {} follow the header",
                     message_type_name(header.type), header.payload_bytes, available);
  }
  if (available > header.payload_bytes) {
    throw make_error(ErrorCode::kInvalidInput, "frame: {} bytes after the {} payload",
                     available - header.payload_bytes, message_type_name(header.type));
  }
  return decode_payload(header, frame.subspan(kFrameHeaderBytes));
}

}  // namespace strielad::protocol
