// SPDX-License-Identifier: Apache-2.0
// The benchmark input: a generated sample dataset (lib/synthetic) of the requested size, one
// file per time step, reused from an earlier run when a stamp in its directory says it
// was made with the same grid, steps, variables and seed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "grid/axis.h"

namespace strielad::bench {

struct SampleInputSpec {
  Dims3 dims;
  std::size_t steps = 1;
  std::vector<std::string> variables;
  std::uint64_t seed = 1;
};

struct SampleInput {
  std::vector<std::filesystem::path> files;
  std::uint64_t bytes = 0;       // sum of file sizes
  double generate_seconds = 0;   // 0 when reused
  bool reused = false;
};

// Generates (or reuses) the dataset in `dir`. Throws what the generator throws.
SampleInput ensure_sample_input(const SampleInputSpec& spec, const std::filesystem::path& dir);

// Converts the input's `variables` into the store `dir` with brick `brick` (the
// converter's default codec), reusing a complete store of the same plan and starting
// over when the directory holds something else. Throws what the converter throws.
void convert_sample_store(const SampleInput& input, const std::vector<std::string>& variables,
                          std::uint32_t brick, int threads, const std::filesystem::path& dir);

}  // namespace strielad::bench
