// SPDX-License-Identifier: Apache-2.0
// A list of octree nodes run through the server's node task (serve/node_executor.h: the
// code a server runs for each node of a cut) on a fresh store and a fresh brick cache,
// on one or more threads, with what it cost: nodes extracted and skipped, bricks read and
// decompressed, bytes fetched and bytes of NodeResult frames a client would receive.
// The scene-economy and scaling suites measure with it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "octree/octree_layout.h"
#include "scene/scene.h"

namespace strielad::bench {

struct NodeBatchCost {
  std::size_t nodes = 0;         // asked for
  std::size_t extracted = 0;     // with some sub-volume read and extracted
  std::size_t skipped = 0;       // every sub-volume skipped from the index alone
  std::uint64_t bricks = 0;      // chunks read from disk and decompressed
  std::uint64_t bytes_read = 0;  // compressed chunks and index bytes the store fetched
  std::uint64_t bytes_sent = 0;  // NodeResult frames
  std::size_t variables_read = 0;  // distinct variables with a brick read
  double seconds = 0;            // wall time of the node tasks (store opened before)
};

// Opens `store_dir` afresh (its counters and index cache start empty) and runs every node
// with `threads` workers (0: all cores) sharing one brick cache of `cache_bytes`.
// \error kInternal when a node fails; what opening the store or the scene throws.
NodeBatchCost run_node_batch(const std::filesystem::path& store_dir, const Scene& scene,
                             const std::vector<NodeId>& nodes, int threads = 1,
                             std::uint64_t cache_bytes = std::uint64_t{8} << 30);

// Every node of one octree level, in id order.
std::vector<NodeId> level_nodes(const OctreeLayout& layout, std::uint32_t level);

}  // namespace strielad::bench
