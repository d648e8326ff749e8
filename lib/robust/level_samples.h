// SPDX-License-Identifier: Apache-2.0
// One whole octree level of one variable at one step, assembled from the level's bricks:
// what the robustness checks compare with their references and what advection reads as
// wind. Neighbouring bricks share their boundary samples; those must agree bit for bit.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "store/store.h"

namespace strielad::robust {

struct LevelSamples {
  std::array<std::size_t, 3> dims{};  // the level's samples along x, y, z
  std::vector<double> values;         // x fastest; NaN = missing
  std::uint64_t shared_mismatches = 0;  // shared boundary samples that differ between bricks
};

// \error the store's read errors (kCorrupt naming file, variable and node).
LevelSamples read_level_samples(const Store& store, std::uint32_t step, std::uint32_t variable,
                                std::size_t level);

}  // namespace strielad::robust
