// SPDX-License-Identifier: Apache-2.0
// Fuzzes the protocol frame decoder (formats/protocol.md) with the receiving side's limit: it
// must reject with strielad::Error, never crash or allocate what the bytes do not
// justify. A frame that decodes must encode again; without a mesh the encoding is the
// input, byte for byte; with one, decoding the new frame gives the same message with
// meshes within the documented quantization bounds (NaN attributes stay NaN, so ==
// cannot be used). Anything else is a bug and aborts.
#include <algorithm>
#include <cstdlib>
#include <span>
#include <variant>

#include "core/error.h"
#include "fuzz/fuzz_target.h"
#include "protocol/message_codec.h"
#include "protocol/sample_messages.h"

using namespace strielad;
using namespace strielad::protocol;

namespace {

bool has_mesh(const Message& m) {
  const auto* result = std::get_if<NodeResult>(&m);
  if (result == nullptr) return false;
  for (const auto& s : result->subvolumes) {
    if (s.outcome == NodeOutcome::kMesh) return true;
  }
  for (const auto& s : result->slices) {
    if (s.outcome == NodeOutcome::kMesh) return true;
  }
  return false;
}

// Equal, except that meshes need only be within the quantization bounds.
bool equivalent(const Message& original, const Message& decoded) {
  if (!has_mesh(original)) return original == decoded;
  const auto& a = std::get<NodeResult>(original);
  const auto* b = std::get_if<NodeResult>(&decoded);
  if (b == nullptr || a.generation != b->generation || a.node != b->node ||
      a.subvolumes.size() != b->subvolumes.size() || a.slices.size() != b->slices.size()) {
    return false;
  }
  for (std::size_t i = 0; i < a.subvolumes.size(); ++i) {
    const auto& s = a.subvolumes[i];
    const auto& t = b->subvolumes[i];
    if (s.subvolume_id != t.subvolume_id || s.outcome != t.outcome || s.reason != t.reason) {
      return false;
    }
    if (s.outcome == NodeOutcome::kMesh ? !samples::mesh_within_bounds(s.mesh, t.mesh)
                                        : !(s.mesh == t.mesh)) {
      return false;
    }
  }
  for (std::size_t i = 0; i < a.slices.size(); ++i) {  // version 2: slice results
    const auto& s = a.slices[i];
    const auto& t = b->slices[i];
    if (s.slice_id != t.slice_id || s.outcome != t.outcome || s.reason != t.reason) return false;
    if (s.outcome == NodeOutcome::kMesh ? !samples::mesh_within_bounds(s.mesh, t.mesh)
                                        : !(s.mesh == t.mesh)) {
      return false;
    }
  }
  return true;
}

// A version-2 NodeResult with a slice mesh and a skipped slice.
NodeResult slice_result_seed() {
  Mesh m;
  m.positions = {{5.0, 50.0, 500.0}, {6.0, 50.0, 500.0}, {6.0, 51.0, 500.0}};
  m.normals.assign(3, {0, 0, 1});
  m.triangles = {{0, 1, 2}};
  m.face_kinds = {FaceKind::kSlice};
  m.attributes = {{250.0f, 260.0f, 270.0f}};
  NodeResult r;
  r.generation = 2;
  r.node = 9;
  r.subvolumes.push_back({1, NodeOutcome::kEmpty, "", {}, {}});
  r.slices.push_back({3, NodeOutcome::kMesh, "", m});
  r.slices.push_back({4, NodeOutcome::kSkippedDomain, "misses", {}});
  return r;
}

}  // namespace

std::vector<std::vector<std::uint8_t>> strielad_fuzz_seeds() {
  std::vector<std::vector<std::uint8_t>> seeds;
  std::vector<Message> messages = samples::sample_messages();
  messages.emplace_back(slice_result_seed());
  for (const Message& m : messages) {
    const auto frame = encode_frame(m);
    const auto* p = reinterpret_cast<const std::uint8_t*>(frame.data());
    seeds.emplace_back(p, p + frame.size());
  }
  return seeds;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::byte> input(reinterpret_cast<const std::byte*>(data), size);
  // Each side decodes with its own limit: a server decodes client frames, and back.
  std::uint32_t limit = kMaxServerPayloadBytes;
  if (size >= kFrameHeaderBytes) {
    const auto type = static_cast<MessageType>(data[4] | data[5] << 8);
    if (is_client_message(type)) limit = kMaxClientPayloadBytes;
  }
  Message message;
  try {
    message = decode_frame(input, limit);
  } catch (const Error&) {
    return 0;
  }
  try {
    const std::vector<std::byte> frame = encode_frame(message);
    const bool same_bytes = frame.size() == size && std::equal(frame.begin(), frame.end(), input.begin());
    if (!has_mesh(message) && !same_bytes) std::abort();
    if (!equivalent(message, decode_frame(frame, limit))) std::abort();
  } catch (const Error&) {
    std::abort();
  }
  return 0;
}
