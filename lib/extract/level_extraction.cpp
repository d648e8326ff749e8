// SPDX-License-Identifier: Apache-2.0
#include "extract/level_extraction.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <optional>
#include <chrono>

#include "core/error.h"
#include "store/brick_cache.h"
#include "store/store.h"

namespace strielad {

LevelExtraction extract_level(const Store& store, const ResolvedScene& scene,
                              const LevelExtractionOptions& options) {
  const OctreeLayout& octree = store.octree();
  if (options.level >= octree.level_count()) {
    throw make_error(ErrorCode::kInvalidArgument, "level {} does not exist: {} has levels 0..{}",
                     options.level, store.path().string(), octree.level_count() - 1);
  }
  if (options.step >= store.step_count() || !store.has_step(options.step)) {
    throw make_error(ErrorCode::kNotFound, "time step {} is not in {} ({} steps)", options.step,
                     store.path().string(), store.step_count());
  }
  // Node ids of a level are contiguous, level 0 first.
  NodeId first = 0;
  for (std::uint32_t l = 0; l < options.level; ++l) first += octree.level(l).node_count();
  const std::size_t count = octree.level(options.level).node_count();

  LevelExtraction out;
  out.nodes.resize(count);
  std::optional<BrickCache> own_cache;
  BrickCache& cache = options.cache ? *options.cache : own_cache.emplace(options.cache_bytes);
  const StoreReadCounters before = store.counters();
  std::atomic<std::uint64_t> done{0};
  const auto start = std::chrono::steady_clock::now();
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  tbb::enumerable_thread_specific<ExtractScratch> scratch;  // one per worker thread
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        ExtractScratch& own = scratch.local();
                        for (std::size_t i = r.begin(); i != r.end(); ++i) {
                          out.nodes[i] = extract_node(store, &cache, scene, options.step,
                                                      static_cast<NodeId>(first + i), own, {},
                                                      NodeMeshOptions{options.merge_face_squares,
                                                                      options.axis_normals});
                          const std::uint64_t d = done.fetch_add(1) + 1;
                          if (options.progress) options.progress(d, count);
                        }
                      });
  });
  LevelExtractionTotals& t = out.totals;
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const StoreReadCounters after = store.counters();
  t.chunks_read = after.chunks_read - before.chunks_read;
  t.chunk_bytes = after.chunk_bytes - before.chunk_bytes;
  t.nodes = count;
  for (const NodeExtraction& n : out.nodes) {
    t.bricks_used += n.bricks_used;
    for (const SubVolumeResult& r : n.results) {
      ++t.outcomes[static_cast<std::size_t>(r.outcome)];
      t.cells += r.stats.cells;
      t.cut_cells += r.stats.cut_cells;
      t.triangles += r.mesh.triangle_count();
      t.vertices += r.mesh.vertex_count();
    }
  }
  return out;
}

Mesh seamless_union(const LevelExtraction& level, std::uint32_t subvolume_id) {
  Mesh joined;
  joined.subvolume_id = subvolume_id;
  for (const NodeExtraction& n : level.nodes) {
    for (const SubVolumeResult& r : n.results) {
      if (r.subvolume_id != subvolume_id || r.outcome != NodeOutcome::kMesh) continue;
      const auto offset = static_cast<std::uint32_t>(joined.positions.size());
      joined.positions.insert(joined.positions.end(), r.mesh.positions.begin(),
                              r.mesh.positions.end());
      joined.normals.insert(joined.normals.end(), r.mesh.normals.begin(), r.mesh.normals.end());
      for (std::size_t t = 0; t < r.mesh.triangles.size(); ++t) {
        if (r.mesh.face_kinds[t] == FaceKind::kNodeBoundary) continue;
        const auto& tri = r.mesh.triangles[t];
        joined.triangles.push_back({tri[0] + offset, tri[1] + offset, tri[2] + offset});
        joined.face_kinds.push_back(r.mesh.face_kinds[t]);
      }
    }
  }
  return joined;
}

}  // namespace strielad
