// SPDX-License-Identifier: Apache-2.0
// Fuzzes the decoders of the messages between strielad-serve's MPI ranks
// (lib/serve/mpi_messages.h): every decoder gets every input. Each must reject or
// decode, never crash, and what it decodes must encode back to the same bytes.
#include <cstdlib>
#include <cstring>

#include "core/error.h"
#include "fuzz/fuzz_target.h"
#include "serve/mpi_messages.h"

using namespace strielad;
using namespace strielad::serve;
using namespace strielad::serve::mpi;

namespace {

std::vector<std::uint8_t> to_u8(const std::vector<std::byte>& b) {
  return {reinterpret_cast<const std::uint8_t*>(b.data()),
          reinterpret_cast<const std::uint8_t*>(b.data()) + b.size()};
}

void expect_same(const std::vector<std::byte>& encoded, std::span<const std::byte> input) {
  if (encoded.size() != input.size() ||
      (!input.empty() && std::memcmp(encoded.data(), input.data(), input.size()) != 0)) {
    std::abort();  // decoded, but the message does not encode back to its bytes
  }
}

}  // namespace

std::vector<std::vector<std::uint8_t>> strielad_fuzz_seeds() {
  WorkerReady ready{8, 1 << 30, std::nullopt, "node17", ""};
  WorkerReady failed{0, 0, ErrorCode::kNotFound, "node18", "no such dataset 'x'"};
  SceneDefinition scene{7, "wind", R"({"time": 2, "subvolumes": []})"};
  TaskRequest task{42, TaskKind::kExtract, 3, 1234, 7};
  TaskRequest prefetch{43, TaskKind::kPrefetch, 3, 9, 8};
  TaskReply reply;
  reply.id = 42;
  reply.kind = NodeOutputKind::kMesh;
  reply.bricks = 8;
  reply.cache = {10, 2, 1, 4096, 1 << 20, 3};
  reply.slice_meshes = 1;
  reply.slice_triangles = 17;
  reply.frame = {std::byte{1}, std::byte{2}, std::byte{3}};
  TaskReply cancelled;
  cancelled.id = 43;
  cancelled.kind = NodeOutputKind::kCancelled;
  return {to_u8(encode(ready)), to_u8(encode(failed)), to_u8(encode(scene)), to_u8(encode(task)),
          to_u8(encode(prefetch)), to_u8(encode(reply)), to_u8(encode(cancelled)),
          to_u8(encode_cancel(42))};
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  try {
    expect_same(encode(decode_ready(bytes)), bytes);
  } catch (const Error&) {
  }
  try {
    expect_same(encode(decode_scene(bytes)), bytes);
  } catch (const Error&) {
  }
  try {
    expect_same(encode(decode_task(bytes)), bytes);
  } catch (const Error&) {
  }
  try {
    expect_same(encode(decode_reply(bytes)), bytes);
  } catch (const Error&) {
  }
  try {
    expect_same(encode_cancel(decode_cancel(bytes)), bytes);
  } catch (const Error&) {
  }
  return 0;
}
