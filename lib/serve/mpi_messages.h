// SPDX-License-Identifier: Apache-2.0
// The messages between the ranks of strielad-serve under MPI (docs/cluster.md). Every
// message is a byte buffer on MPI_COMM_WORLD whose MPI tag names its type; fields are
// little-endian (core/byte_io.h). No MPI here: lib/serve/mpi_runtime.h moves the bytes.
//
//   tag      direction        payload
//   kReady   worker -> 0      WorkerReady, once, first
//   kScene   0 -> worker      SceneDefinition, before the first TaskRequest naming it
//   kTask    0 -> worker      TaskRequest
//   kCancel  0 -> worker      u64 request id (the request may be finished already)
//   kStop    0 -> worker      nothing; the last message rank 0 sends to that worker
//   kReply   worker -> 0      TaskReply, exactly one per TaskRequest received before kStop
//   kStopped worker -> 0      nothing; the last message the worker sends
//
// A scene travels once per worker and generation: a worker keeps the last kWorkerScenes
// scenes it was sent, forgetting the oldest; rank 0 keeps the same list per worker and
// sends a scene again only once the worker has forgotten it. MPI keeps the messages of
// one rank to another in order, so a task never arrives before its scene.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/error.h"
#include "octree/octree_layout.h"
#include "serve/node_executor.h"
#include "store/brick_cache.h"

namespace strielad::serve::mpi {

enum Tag : int {
  kReady = 1,
  kTask = 2,
  kCancel = 3,
  kStop = 4,
  kReply = 5,
  kStopped = 6,
  kScene = 7,
};

inline constexpr std::size_t kWorkerScenes = 32;

struct WorkerReady {
  std::uint32_t threads = 0;       // tasks the worker runs at once
  std::uint64_t cache_budget = 0;  // bytes of its brick cache
  std::optional<ErrorCode> error;  // set: it cannot serve, `message` says why
  std::string host;
  std::string message;
};

// A generation's scene at one time step, parsed and resolved by the worker once.
struct SceneDefinition {
  std::uint64_t id = 0;    // unique per rank 0 (serve::SceneSource::id)
  std::string dataset;     // name under the server root, opened by the worker's own registry
  std::string scene_json;  // canonical scene; its "time" is the step
};

enum class TaskKind : std::uint8_t { kExtract = 0, kPrefetch = 1 };

struct TaskRequest {
  std::uint64_t id = 0;  // unique per rank 0; names the reply and a cancel
  TaskKind kind = TaskKind::kExtract;
  std::uint32_t generation = 0;
  NodeId node = 0;
  std::uint64_t scene = 0;  // id of a SceneDefinition the worker holds: dataset and scene
};

struct TaskReply {
  std::uint64_t id = 0;
  NodeOutputKind kind = NodeOutputKind::kCancelled;
  std::uint32_t bricks = 0;  // extract: bricks used
  std::uint64_t loaded = 0;  // prefetch: bricks loaded into the worker's cache
  BrickCacheStats cache;     // the worker's cache after the task
  std::uint32_t slice_meshes = 0;     // extract: as NodeOutput
  std::uint64_t slice_triangles = 0;
  std::vector<std::byte> frame;  // encoded NodeResult or NodeFailed (extract only)
};

std::vector<std::byte> encode(const WorkerReady& m);
std::vector<std::byte> encode(const SceneDefinition& m);
std::vector<std::byte> encode(const TaskRequest& m);
std::vector<std::byte> encode(const TaskReply& m);
std::vector<std::byte> encode_cancel(std::uint64_t id);

// \error kTruncated or kCorrupt for bytes no peer of this version writes.
WorkerReady decode_ready(std::span<const std::byte> bytes);
SceneDefinition decode_scene(std::span<const std::byte> bytes);
TaskRequest decode_task(std::span<const std::byte> bytes);
TaskReply decode_reply(std::span<const std::byte> bytes);
std::uint64_t decode_cancel(std::span<const std::byte> bytes);

}  // namespace strielad::serve::mpi
