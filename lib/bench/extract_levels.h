// SPDX-License-Identifier: Apache-2.0
// "Error against run time" of `strielad-bench extract`: for a one-sub-volume scene, every
// octree level of a store extracted whole with extract_level (all cores and one thread),
// and per level the error to full resolution: the enclosed volume of the seamless union
// (the per-node meshes are closed, so their volumes add up exactly) against level 0's,
// and the mean distance between the level's limit surface and level 0's. Also OpenVDB's
// volumeToMesh on the whole level-0 grid of a sparse variable, where its per-call setup
// is paid once instead of per brick.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "bench/extract_bricks.h"

namespace strielad {
class Store;
}

namespace strielad::bench {

struct LevelRow {
  std::uint32_t level = 0;
  std::array<std::size_t, 3> samples{};  // of the level's grid
  std::array<std::size_t, 3> stride{};   // level-0 samples per step of the level
  std::uint64_t nodes = 0;               // of the level
  std::uint64_t extracted = 0;           // nodes whose bricks were read and meshed
  std::uint64_t skipped = 0;             // nodes left out from the index alone
  std::uint64_t chunks_read = 0;         // bricks decompressed (one run)
  std::uint64_t cut_cells = 0;
  std::vector<double> seconds_all;       // wall seconds per round, threads = all cores
  std::vector<double> seconds_one;       // the same, one thread
  std::uint64_t triangles = 0;           // every triangle of every node mesh
  std::uint64_t seamless_triangles = 0;  // without the faces shared by neighbouring nodes
  std::uint64_t limit_vertices = 0;      // vertices of limit-surface triangles
  double volume = 0;                     // axis units (deg x deg x m for the sample data)
  double volume_error = 0;               // (volume - volume at level 0) / volume at level 0
  // Distances in level-0 index space (level-0 cells, each axis in its own cells), exact
  // point-to-triangle: mean over this level's distinct limit-surface vertices of the
  // distance to level 0's limit surface, and the mean over level 0's vertices of the
  // distance to this level's; NaN when a side has no surface.
  double distance_to_fine = 0, distance_from_fine = 0;
  double distance_to_fine_p90 = 0;
  double distance() const { return 0.5 * (distance_to_fine + distance_from_fine); }
  double median_all() const;
  double median_one() const;
};

struct LevelGroup {
  ExtractCase extract_case;
  std::uint32_t brick = 0;
  int threads_all = 0;         // what "all cores" was
  std::vector<LevelRow> rows;  // level 0 first
};

struct LevelGroupOptions {
  int threads = 0;  // "all cores" runs; 0 = hardware concurrency
  int repeat = 3;
};

// \error kNotFound for a case variable the store lacks.
LevelGroup run_level_group(const Store& store, const ExtractCase& extract_case,
                           const LevelGroupOptions& options);

// One case extracted whole at level 0 from two stores of the same grid (a reference and,
// e.g., a lossy copy): the enclosed volumes and the distance between their limit
// surfaces (level-0 cells, mean over both directions, and the larger p90 and max).
struct SurfaceComparison {
  std::string case_name;
  double reference_volume = 0, volume = 0;
  double volume_error = 0;  // (volume - reference_volume) / reference_volume
  double distance_mean = 0, distance_p90 = 0, distance_max = 0;
  std::uint64_t reference_triangles = 0, triangles = 0;
};

// \error kNotFound for a case variable the stores lack.
SurfaceComparison compare_level0_surfaces(const Store& reference, const Store& other,
                                          const ExtractCase& extract_case);

struct WholeLevelVdb {
  std::string case_name;
  std::uint32_t level = 0;
  std::uint64_t active_voxels = 0;
  double build_seconds = 0;          // vdb::build_level_grid from the store (all cores)
  std::vector<double> mesh_seconds;  // tools::volumeToMesh, one thread, per round
  std::uint64_t triangles = 0;       // quads count as two
  double volume = 0;                 // mapped to axis units, |divergence volume|
  double kernel_volume = 0;          // the level group's level-0 volume
  double kernel_seconds_one = 0;     // the level group's level-0 one-thread median
};

// OpenVDB on the whole grid of `level` of the case's (one, min) limit variable, whose
// background 0 lies below the threshold: the grid's inactive voxels are outside, so the
// surface closes, also half a voxel beyond the grid's edge where a cloud touches it.
// Returns nothing for a case that is not one min limit above 0.
std::optional<WholeLevelVdb> run_whole_level_vdb(const Store& store, const ExtractCase& c,
                                                 std::uint32_t level, int repeat);

}  // namespace strielad::bench
