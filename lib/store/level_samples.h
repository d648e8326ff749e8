// SPDX-License-Identifier: Apache-2.0
// One octree level of one variable at one step put together from the level's bricks: the
// one place that walks a level's bricks and places their samples in the level's grid.
// Advection reads its wind this way, the robustness checks their levels, the VDB export
// its grids. Neighbouring bricks share their boundary samples, which must agree bit for
// bit (any NaN equals any NaN); the dense assembly counts those that do not.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "store/brick.h"
#include "store/store.h"

namespace strielad {

// Which bricks to read, decided from the index entry alone (no read); empty: all of them.
using BrickWanted = std::function<bool(const format::IndexEntry&)>;

struct LevelBrickCounts {
  std::uint64_t bricks_read = 0;
  std::uint64_t bricks_skipped = 0;  // left out by `wanted`
  std::uint64_t sample_bytes = 0;    // bytes of the read data bricks' samples (decoded)
};

// Hands every wanted brick of `level` to `place`, one at a time and in node order (so a
// sample shared by bricks ends with the last brick's value); the bricks are read and
// decompressed in parallel batches ahead of it. The brick's sample (x, y, z) is the
// level's sample brick.box.lo + (x, y, z). \error kNotFound naming the store when
// `level` is not in the octree; the store's read errors (kCorrupt naming file,
// variable and node).
LevelBrickCounts for_each_level_brick(const Store& store, std::uint32_t step,
                                      std::uint32_t variable, std::uint32_t level,
                                      const std::function<void(const Brick&)>& place,
                                      const BrickWanted& wanted = {});

template <typename T>
struct LevelSamples {
  std::array<std::size_t, 3> dims{};    // the level's samples along x, y, z
  std::vector<T> values;                // x fastest; NaN = missing or in a brick not wanted
  LevelBrickCounts counts;
  std::uint64_t shared_mismatches = 0;  // shared boundary samples that differ between bricks
};

// The whole level as one dense grid of T (float64 samples rounded for float).
// \error as for_each_level_brick.
template <typename T>
LevelSamples<T> read_level_samples(const Store& store, std::uint32_t step, std::uint32_t variable,
                                   std::uint32_t level, const BrickWanted& wanted = {});

extern template LevelSamples<float> read_level_samples<float>(const Store&, std::uint32_t,
                                                              std::uint32_t, std::uint32_t,
                                                              const BrickWanted&);
extern template LevelSamples<double> read_level_samples<double>(const Store&, std::uint32_t,
                                                                std::uint32_t, std::uint32_t,
                                                                const BrickWanted&);

}  // namespace strielad
