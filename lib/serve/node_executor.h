// SPDX-License-Identifier: Apache-2.0
// What runs one scheduled node: extraction into an encoded NodeResult frame (or a
// NodeFailed frame), and prefetching of the bricks a node will need. The threaded
// server runs nodes in-process (LocalNodeExecutor); under MPI they run on worker ranks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <stop_token>
#include <string>
#include <vector>

#include "octree/octree_layout.h"
#include "scene/scene.h"
#include "store/brick_cache.h"

namespace strielad {
class Store;
}

namespace strielad::serve {

// A generation's scene at one time step as another process resolves it (an MPI worker
// rank): its canonical JSON, written once per generation and step, and an id unique in
// this process by which the worker keeps it once parsed and resolved.
struct SceneSource {
  std::uint64_t id = 0;
  std::string json;  // canonical scene (formats/scene.md) with that time step
};

// A new SceneSource id (thread-safe; never 0).
std::uint64_t next_scene_source_id();

struct NodeTask {
  std::shared_ptr<const Store> store;
  std::string dataset;                        // the name the client opened it by
  std::shared_ptr<const ResolvedScene> scene;  // scene->time is the step to extract
  // The same scene, shared by every task of the generation; null where no executor
  // needs it (a worker rank's own tasks).
  std::shared_ptr<const SceneSource> scene_source;
  std::uint32_t generation = 0;
  NodeId node = 0;
  std::uint64_t serial = 0;  // tells a re-added node's new task from its old one
  std::stop_token stop;
};

enum class NodeOutputKind : std::uint8_t {
  kMesh,       // at least one sub-volume or slice has triangles
  kEmpty,      // extracted, nothing inside
  kSkipped,    // every sub-volume and slice skipped from the index alone (no brick read)
  kFailed,     // frame is a NodeFailed
  kCancelled,  // stop was requested; frame is empty
};

struct NodeOutput {
  NodeOutputKind kind = NodeOutputKind::kCancelled;
  std::vector<std::byte> frame;  // encoded NodeResult or NodeFailed
  std::uint32_t bricks = 0;      // bricks used (cache or disk)
  std::uint32_t slice_meshes = 0;      // slice results with a mesh (outcome kMesh)
  std::uint64_t slice_triangles = 0;   // their triangles
};

// `should_yield` is polled between bricks; returns the bricks loaded into the cache.
using YieldCheck = std::function<bool()>;

class NodeExecutor {
 public:
  virtual ~NodeExecutor() = default;
  virtual NodeOutput execute(const NodeTask& task) = 0;
  virtual std::size_t prefetch(const NodeTask& task, const YieldCheck& should_yield) = 0;
  // Cache statistics summed over every cache the executor uses.
  virtual BrickCacheStats cache_stats() const = 0;
  virtual std::size_t ranks() const { return 1; }
};

// Extracts on the calling thread through one shared bytes-bounded brick cache.
class LocalNodeExecutor final : public NodeExecutor {
 public:
  explicit LocalNodeExecutor(std::uint64_t cache_bytes) : cache_(cache_bytes) {}
  NodeOutput execute(const NodeTask& task) override;
  std::size_t prefetch(const NodeTask& task, const YieldCheck& should_yield) override;
  BrickCacheStats cache_stats() const override { return cache_.stats(); }
  BrickCache& cache() { return cache_; }

 private:
  BrickCache cache_;
};

// The extraction itself, shared by the local executor and MPI worker ranks.
NodeOutput run_node_task(const NodeTask& task, BrickCache& cache);
std::size_t prefetch_node_task(const NodeTask& task, BrickCache& cache,
                               const YieldCheck& should_yield);

}  // namespace strielad::serve
