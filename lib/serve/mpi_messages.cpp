// SPDX-License-Identifier: Apache-2.0
#include "serve/mpi_messages.h"

#include "core/byte_io.h"
#include "core/error.h"

namespace strielad::serve::mpi {

namespace {

void put_text(ByteWriter& w, std::string_view text) {
  w.u64(text.size());
  w.text(text);
}

std::string get_text(ByteReader& r, std::string_view field) {
  const std::uint64_t n = r.u64(field);
  if (n > r.remaining()) {
    throw make_error(ErrorCode::kTruncated, "MPI message: field '{}' claims {} bytes, only {} remain",
                     field, n, r.remaining());
  }
  const auto bytes = r.bytes(static_cast<std::size_t>(n), field);
  return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

void expect_end(const ByteReader& r, std::string_view what) {
  if (r.remaining() != 0) {
    throw make_error(ErrorCode::kCorrupt, "MPI message {}: {} bytes after the last field", what,
                     r.remaining());
  }
}

}  // namespace

std::vector<std::byte> encode(const WorkerReady& m) {
  ByteWriter w;
  w.u32(m.threads);
  w.u64(m.cache_budget);
  w.u8(m.error ? static_cast<std::uint8_t>(*m.error) + 1 : 0);
  put_text(w, m.host);
  put_text(w, m.message);
  return w.take();
}

WorkerReady decode_ready(std::span<const std::byte> bytes) {
  ByteReader r(bytes, "MPI message Ready");
  WorkerReady m;
  m.threads = r.u32("threads");
  m.cache_budget = r.u64("cache_budget");
  const std::uint8_t error = r.u8("error");
  if (error > static_cast<std::uint8_t>(ErrorCode::kInternal) + 1) {
    throw make_error(ErrorCode::kCorrupt, "MPI message Ready: unknown error code {}", error - 1);
  }
  if (error) m.error = static_cast<ErrorCode>(error - 1);
  m.host = get_text(r, "host");
  m.message = get_text(r, "message");
  expect_end(r, "Ready");
  return m;
}

std::vector<std::byte> encode(const SceneDefinition& m) {
  ByteWriter w;
  w.u64(m.id);
  put_text(w, m.dataset);
  put_text(w, m.scene_json);
  return w.take();
}

SceneDefinition decode_scene(std::span<const std::byte> bytes) {
  ByteReader r(bytes, "MPI message Scene");
  SceneDefinition m;
  m.id = r.u64("id");
  m.dataset = get_text(r, "dataset");
  m.scene_json = get_text(r, "scene_json");
  expect_end(r, "Scene");
  return m;
}

std::vector<std::byte> encode(const TaskRequest& m) {
  ByteWriter w;
  w.u64(m.id);
  w.u8(static_cast<std::uint8_t>(m.kind));
  w.u32(m.generation);
  w.u32(m.node);
  w.u64(m.scene);
  return w.take();
}

TaskRequest decode_task(std::span<const std::byte> bytes) {
  ByteReader r(bytes, "MPI message Task");
  TaskRequest m;
  m.id = r.u64("id");
  const std::uint8_t kind = r.u8("kind");
  if (kind > static_cast<std::uint8_t>(TaskKind::kPrefetch)) {
    throw make_error(ErrorCode::kCorrupt, "MPI message Task: unknown task kind {}", kind);
  }
  m.kind = static_cast<TaskKind>(kind);
  m.generation = r.u32("generation");
  m.node = r.u32("node");
  m.scene = r.u64("scene");
  expect_end(r, "Task");
  return m;
}

std::vector<std::byte> encode(const TaskReply& m) {
  ByteWriter w;
  w.u64(m.id);
  w.u8(static_cast<std::uint8_t>(m.kind));
  w.u32(m.bricks);
  w.u64(m.loaded);
  for (std::uint64_t v : {m.cache.hits, m.cache.misses, m.cache.evictions, m.cache.bytes,
                          m.cache.budget, m.cache.entries}) {
    w.u64(v);
  }
  w.u32(m.slice_meshes);
  w.u64(m.slice_triangles);
  w.u64(m.frame.size());
  w.bytes(m.frame);
  return w.take();
}

TaskReply decode_reply(std::span<const std::byte> bytes) {
  ByteReader r(bytes, "MPI message Reply");
  TaskReply m;
  m.id = r.u64("id");
  const std::uint8_t kind = r.u8("kind");
  if (kind > static_cast<std::uint8_t>(NodeOutputKind::kCancelled)) {
    throw make_error(ErrorCode::kCorrupt, "MPI message Reply: unknown output kind {}", kind);
  }
  m.kind = static_cast<NodeOutputKind>(kind);
  m.bricks = r.u32("bricks");
  m.loaded = r.u64("loaded");
  m.cache.hits = r.u64("cache.hits");
  m.cache.misses = r.u64("cache.misses");
  m.cache.evictions = r.u64("cache.evictions");
  m.cache.bytes = r.u64("cache.bytes");
  m.cache.budget = r.u64("cache.budget");
  m.cache.entries = r.u64("cache.entries");
  m.slice_meshes = r.u32("slice_meshes");
  m.slice_triangles = r.u64("slice_triangles");
  const std::uint64_t n = r.u64("frame size");
  if (n != r.remaining()) {
    throw make_error(ErrorCode::kCorrupt, "MPI message Reply: frame of {} bytes, {} bytes follow", n,
                     r.remaining());
  }
  const auto frame = r.bytes(static_cast<std::size_t>(n), "frame");
  m.frame.assign(frame.begin(), frame.end());
  return m;
}

std::vector<std::byte> encode_cancel(std::uint64_t id) {
  ByteWriter w;
  w.u64(id);
  return w.take();
}

std::uint64_t decode_cancel(std::span<const std::byte> bytes) {
  ByteReader r(bytes, "MPI message Cancel");
  const std::uint64_t id = r.u64("id");
  expect_end(r, "Cancel");
  return id;
}

}  // namespace strielad::serve::mpi
