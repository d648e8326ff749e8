// SPDX-License-Identifier: Apache-2.0
// OpenVDB views of a store level. This header is free of OpenVDB types so that callers
// do not pay OpenVDB's compile cost; level_grid_openvdb.h hands out the grid itself.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "scene/scene.h"
#include "store/store.h"

namespace strielad::vdb {

struct LevelGridOptions {
  // Voxels equal to the background are left inactive (the sparse VDB convention). Fill
  // (missing) samples are always inactive.
  double background = 0.0;
};

struct LevelGridSummary {
  std::uint64_t active_voxels = 0;
  std::uint64_t bricks_read = 0;
  std::uint64_t bricks_skipped = 0;  // empty, or constant equal to the background
  double min = 0, max = 0;           // of the active voxels
};

// Writes variable `variable` at `step`, octree level `level` as a standard .vdb file
// (one FloatGrid named after the variable), atomically. Index space: voxel (i, j, k) is
// sample (x, y, z) of the level; the grid transform scales by the level's stride, so
// levels overlay in level-0 index space. Axis values and units are grid metadata.
LevelGridSummary write_level_vdb(const Store& store, std::uint32_t step, std::uint32_t variable,
                                 std::uint32_t level, const std::filesystem::path& out,
                                 const LevelGridOptions& options = {});

struct SubVolumeGridSummary {
  std::uint32_t subvolume_id = 0;
  std::uint64_t active_voxels = 0;
  std::uint64_t nodes_skipped = 0;  // by value range, missing data or domain (no read)
  std::uint64_t bricks_read = 0;
};

// Writes one fog volume per sub-volume of `scene` (a FloatGrid named "subvolume-ID" or
// after the sub-volume) at octree level `level`, atomically: density 1 at the samples
// where every limit holds, the sample is valid and inside the domain box; inactive
// elsewhere. Same index-space transform and metadata as write_level_vdb (Blender and
// Houdini read it as a volume; the non-uniform axes are in the metadata).
std::vector<SubVolumeGridSummary> write_subvolume_vdb(const Store& store,
                                                      const ResolvedScene& scene,
                                                      std::uint32_t level,
                                                      const std::filesystem::path& out);

}  // namespace strielad::vdb
