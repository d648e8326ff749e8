// SPDX-License-Identifier: Apache-2.0
// Batch extraction of every node of one octree level that a scene needs, in parallel
// (oneTBB), with totals for `--json` output. Results are in node order whatever the
// thread count, so output files are deterministic.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "extract/node_extraction.h"
#include "scene/scene.h"

namespace strielad {

class BrickCache;

struct LevelExtractionOptions {
  std::uint32_t step = 0;
  std::uint32_t level = 0;
  int threads = 0;                            // 0: all cores
  std::uint64_t cache_bytes = 256ull << 20;   // brick cache shared by the workers
  // A cache to use instead of a fresh one of cache_bytes (kept by the caller across
  // extractions, as the server keeps its cache: a time-invariant geometry field's bricks
  // are then read once for every step).
  BrickCache* cache = nullptr;
  std::function<void(std::uint64_t done, std::uint64_t total)> progress;
  // As ExtractRequest::merge_face_squares: false for output frames that bend the lattice.
  bool merge_face_squares = true;
  // As ExtractRequest::axis_normals: false when the output frame replaces every normal.
  bool axis_normals = true;
};

struct LevelExtractionTotals {
  std::uint64_t nodes = 0;
  std::array<std::uint64_t, 5> outcomes{};  // per NodeOutcome, over node x sub-volume
  std::uint64_t bricks_used = 0;
  std::uint64_t chunks_read = 0;        // data bricks fetched from disk and decompressed
  std::uint64_t chunk_bytes = 0;        // their compressed bytes
  std::uint64_t cells = 0, cut_cells = 0;
  std::uint64_t triangles = 0, vertices = 0;
  double seconds = 0;                   // wall time of the extraction
};

struct LevelExtraction {
  std::vector<NodeExtraction> nodes;  // every node of the level, in node-id order
  LevelExtractionTotals totals;
};

LevelExtraction extract_level(const Store& store, const ResolvedScene& scene,
                              const LevelExtractionOptions& options);

// Every node's mesh of sub-volume `subvolume_id` in one mesh, without the faces shared
// by neighbouring nodes (face kind node-boundary): the seamless surface of the region at
// this level, closed where the region is (formats/scene.md, "Extraction output").
// Attributes are left out.
Mesh seamless_union(const LevelExtraction& level, std::uint32_t subvolume_id);

}  // namespace strielad
