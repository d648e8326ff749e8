// SPDX-License-Identifier: Apache-2.0
// Level 0 of a store's (step, variable) reassembled from its bricks, for tests that
// compare a conversion with its input.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "store/level_samples.h"
#include "store/store.h"

namespace strielad::testing {

// Level 0 of (step, variable), x fastest. Neighbouring bricks share boundary samples;
// each shared sample must be the same in both (checked with EXPECT).
inline std::vector<double> assemble_level0(const Store& store, std::uint32_t step,
                                           std::uint32_t var) {
  LevelSamples<double> level = read_level_samples<double>(store, step, var, 0);
  EXPECT_EQ(level.shared_mismatches, 0u) << "bricks disagree with their neighbours";
  return std::move(level.values);
}

}  // namespace strielad::testing
