// SPDX-License-Identifier: Apache-2.0
#include "serve/node_executor.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <atomic>

#include "core/error.h"
#include "extract/node_extraction.h"
#include "protocol/message_codec.h"
#include "serve/client_error_text.h"
#include "store/store.h"

namespace strielad::serve {

namespace {

std::string clipped(std::string text) {
  if (text.size() > protocol::kMaxMessageTextBytes) {
    text.resize(protocol::kMaxMessageTextBytes - 3);
    // Do not leave half a UTF-8 sequence behind.
    while (!text.empty() && (static_cast<unsigned char>(text.back()) & 0xC0) == 0x80) text.pop_back();
    if (!text.empty() && (static_cast<unsigned char>(text.back()) & 0x80)) text.pop_back();
    text += "...";
  }
  return text;
}

// The client's NodeFailed names the dataset where the error names the store's files; the
// log keeps the paths.
NodeOutput failed(const NodeTask& task, protocol::WireError code, std::string_view message) {
  spdlog::warn("dataset '{}' node {}: {}", task.dataset, task.node, message);
  NodeOutput out;
  out.kind = NodeOutputKind::kFailed;
  out.frame = protocol::encode_frame(protocol::NodeFailed{
      task.generation, task.node, code,
      clipped(name_dataset_not_path(message, task.store->path(), task.dataset))});
  return out;
}

}  // namespace

std::uint64_t next_scene_source_id() {
  static std::atomic<std::uint64_t> next{1};
  return next++;
}

NodeOutput run_node_task(const NodeTask& task, BrickCache& cache) {
  try {
    NodeExtraction extraction =
        extract_node(*task.store, &cache, *task.scene, task.scene->time, task.node, task.stop);
    protocol::NodeResult result;
    result.generation = task.generation;
    result.node = task.node;
    bool any_mesh = false, all_skipped = true;
    for (SubVolumeResult& r : extraction.results) {
      any_mesh |= r.outcome == NodeOutcome::kMesh;
      all_skipped &= r.outcome != NodeOutcome::kMesh && r.outcome != NodeOutcome::kEmpty;
      r.mesh.attribute_names.clear();  // the client knows them from the scene
      r.reason = clipped(std::move(r.reason));
    }
    result.subvolumes = std::move(extraction.results);
    // Slices after the sub-volumes (protocol version 2: the session accepts a scene with
    // slices only on such a connection).
    std::uint32_t slice_meshes = 0;
    std::uint64_t slice_triangles = 0;
    for (SliceResult& s : extraction.slices) {
      any_mesh |= s.outcome == NodeOutcome::kMesh;
      all_skipped &= s.outcome != NodeOutcome::kMesh && s.outcome != NodeOutcome::kEmpty;
      if (s.outcome == NodeOutcome::kMesh) {
        ++slice_meshes;
        slice_triangles += s.mesh.triangle_count();
      }
      s.mesh.attribute_names.clear();
      s.reason = clipped(std::move(s.reason));
    }
    result.slices = std::move(extraction.slices);
    NodeOutput out;
    out.slice_meshes = slice_meshes;
    out.slice_triangles = slice_triangles;
    out.kind = any_mesh ? NodeOutputKind::kMesh
                        : (all_skipped ? NodeOutputKind::kSkipped : NodeOutputKind::kEmpty);
    out.bricks = extraction.bricks_used;
    out.frame = protocol::encode_frame(result);
    return out;
  } catch (const Error& e) {
    if (e.code() == ErrorCode::kCancelled) return NodeOutput{};
    return failed(task, protocol::wire_error(e.code()), e.what());
  } catch (const std::exception& e) {
    return failed(task, protocol::WireError::kInternal, e.what());
  }
}

std::size_t prefetch_node_task(const NodeTask& task, BrickCache& cache,
                               const YieldCheck& should_yield) {
  const std::uint32_t step = task.scene->time;
  std::size_t loaded = 0;
  try {
    for (std::uint32_t variable :
         node_brick_variables(*task.store, *task.scene, step, task.node)) {
      if (task.stop.stop_requested() || should_yield()) break;
      const BrickKey key{task.store.get(), step, variable, task.node};
      if (cache.contains(key)) continue;
      task.store->read_brick(step, variable, task.node, cache);
      ++loaded;
    }
  } catch (const Error&) {
    // A damaged brick is reported when a client asks for the node, not by prefetching.
  }
  return loaded;
}

NodeOutput LocalNodeExecutor::execute(const NodeTask& task) { return run_node_task(task, cache_); }

std::size_t LocalNodeExecutor::prefetch(const NodeTask& task, const YieldCheck& should_yield) {
  return prefetch_node_task(task, cache_, should_yield);
}

}  // namespace strielad::serve
