// SPDX-License-Identifier: Apache-2.0
// What a store costs on disk, per variable of one time step: the variable's chunk bytes
// (sum of chunk_size over its index), its index section, and an equal share of the step
// file's fixed parts (header, section table, footer); split into level 0 and coarse
// levels for the octree's stored-bytes overhead. Plus the brick kinds.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace strielad::bench {

struct VariableStoreSize {
  std::string name;
  std::uint64_t raw_bytes = 0;           // samples x dtype size (level 0 only)
  std::uint64_t chunk_bytes = 0;         // all levels
  std::uint64_t level0_chunk_bytes = 0;
  std::uint64_t coarse_chunk_bytes = 0;
  std::uint64_t index_bytes = 0;         // the variable's stored index section
  double fixed_share_bytes = 0;          // header + section table + footer / variables
  std::uint64_t data = 0, constant = 0, empty = 0;  // bricks, all levels

  double store_bytes() const {
    return static_cast<double>(chunk_bytes + index_bytes) + fixed_share_bytes;
  }
};

struct StoreSizes {
  std::vector<VariableStoreSize> variables;
  std::uint64_t step_file_bytes = 0;
  std::size_t node_count = 0, levels = 0;
  std::uint32_t brick = 0;
  double overhead_fraction = 0;  // OctreeLayout::overhead_fraction (samples)

  // Coarse chunk bytes / level-0 chunk bytes over all variables.
  double stored_overhead() const;
  const VariableStoreSize* find(const std::string& name) const;
};

// Sizes of step 0 of the store. Throws what Store throws.
StoreSizes measure_store_sizes(const std::filesystem::path& store);

}  // namespace strielad::bench
