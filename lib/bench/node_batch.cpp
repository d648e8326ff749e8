// SPDX-License-Identifier: Apache-2.0
#include "bench/node_batch.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>

#include "core/error.h"
#include "extract/node_extraction.h"
#include "serve/node_executor.h"
#include "store/brick_cache.h"
#include "store/store.h"

namespace strielad::bench {

NodeBatchCost run_node_batch(const std::filesystem::path& store_dir, const Scene& scene,
                             const std::vector<NodeId>& nodes, int threads,
                             std::uint64_t cache_bytes) {
  const auto store = Store::open(store_dir);
  auto resolved =
      std::make_shared<const ResolvedScene>(resolve_scene(scene, store->manifest(), "scene"));
  BrickCache cache(cache_bytes);
  std::atomic<std::size_t> extracted{0}, skipped{0};
  std::atomic<std::uint64_t> sent{0};
  std::atomic<bool> failed{false};
  std::atomic<NodeId> failed_node{0};
  std::mutex variables_mutex;
  std::set<std::uint32_t> variables;
  const auto t0 = std::chrono::steady_clock::now();
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, nodes.size(), 1),
        [&](const tbb::blocked_range<std::size_t>& r) {
          for (std::size_t i = r.begin(); i != r.end(); ++i) {
            serve::NodeTask task;
            task.store = store;
            task.scene = resolved;
            task.generation = 1;
            task.node = nodes[i];
            const serve::NodeOutput out = serve::run_node_task(task, cache);
            switch (out.kind) {
              case serve::NodeOutputKind::kMesh:
              case serve::NodeOutputKind::kEmpty: {
                ++extracted;
                const auto used =
                    node_brick_variables(*store, *resolved, resolved->time, nodes[i]);
                const std::lock_guard lock(variables_mutex);
                variables.insert(used.begin(), used.end());
                break;
              }
              case serve::NodeOutputKind::kSkipped: ++skipped; break;
              case serve::NodeOutputKind::kFailed:
                failed_node = nodes[i];
                failed = true;
                break;
              case serve::NodeOutputKind::kCancelled: break;
            }
            sent += out.frame.size();
          }
        });
  });
  if (failed) {
    throw make_error(ErrorCode::kInternal, "{}: node {} failed", store_dir.string(),
                     failed_node.load());
  }
  NodeBatchCost cost;
  cost.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  cost.nodes = nodes.size();
  cost.extracted = extracted;
  cost.skipped = skipped;
  cost.bytes_sent = sent;
  cost.variables_read = variables.size();
  const StoreReadCounters c = store->counters();
  cost.bricks = c.chunks_read;
  cost.bytes_read = c.chunk_bytes + c.index_bytes;
  return cost;
}

std::vector<NodeId> level_nodes(const OctreeLayout& layout, std::uint32_t level) {
  const LevelShape& shape = layout.level(level);
  std::vector<NodeId> ids(shape.node_count());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = static_cast<NodeId>(shape.first_node + i);
  return ids;
}

}  // namespace strielad::bench
