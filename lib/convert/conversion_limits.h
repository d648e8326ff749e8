// SPDX-License-Identifier: Apache-2.0
// What a planned conversion needs, decided from the grid's size alone, so that an input
// too large for the format or the machine is refused with a clear message before
// anything is read or allocated (docs/robustness.md, "Very large grids"):
// - a brick must fit one Blosc chunk (c-blosc 1 buffers hold at most 2^31 - 17 bytes;
//   the index's chunk_size is a u32);
// - the converter's peak memory must fit the limit: it streams level 0 one brick layer
//   (a slab of at most B + 3 whole xy-planes) at a time, with up to max(2, threads) slabs
//   in flight, and holds level 1 (a quarter of level 0 or less) whole.
// Sizes are computed in floating point, so no grid overflows them.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "grid/axis.h"
#include "octree/octree_layout.h"

namespace strielad::build {

// The most bytes one chunk may hold (BLOSC_MAX_BUFFERSIZE).
std::uint64_t max_chunk_bytes();

// \error kInvalidArgument when the layout's largest brick of `dtype` samples is larger
// than one chunk; the message names `variable`, the brick's size and the largest brick
// size that fits this grid.
void check_brick_fits_chunk(const OctreeLayout& layout, DType dtype, std::string_view variable);

struct ConversionMemory {
  double slab_bytes = 0;    // one slab of level 0 in the store type
  int slabs = 0;            // slabs in flight
  double coarse_bytes = 0;  // level 1 held whole, its encoded bricks and level 2
  double total_bytes = 0;   // the estimated peak of converting one variable
};

// `threads`: the converter's threads (0 = all cores); `source_bytes`: bytes per sample in
// the NetCDF file (the raw read buffer of a slab).
ConversionMemory estimate_conversion_memory(const OctreeLayout& layout, DType dtype,
                                            std::size_t source_bytes, int threads);

// Physical memory, or the cgroup's memory limit when that is smaller; 0 when unknown.
std::uint64_t available_memory_bytes();

// \error kUnsupported when the estimate for `variable` exceeds `limit_bytes` (0: the
// available memory; no check when that is unknown): names the grid, the variable, the
// estimate and its parts, the limit, and what to do.
void check_conversion_memory(const OctreeLayout& layout, DType dtype, std::size_t source_bytes,
                             int threads, std::uint64_t limit_bytes, std::string_view variable);

}  // namespace strielad::build
