// SPDX-License-Identifier: Apache-2.0
// `--predictor auto`: the converter decides per variable, at plan time, whether the
// lorenzo3 predictor (formats/store.md, "Predictors") makes its chunks smaller. Dense,
// smooth fields (temperature, wind) shrink by half or more; sparse cloud fields mostly
// grow.
// The decision is part of the plan (it changes the store_id), so it must come out the
// same in every process that converts part of the store (Slurm array tasks): it looks
// only at time step 0 and at bricks chosen by the grid and brick size alone.
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "format/manifest.h"
#include "ingest/input_catalog.h"
#include "octree/octree_layout.h"

namespace strielad::build {

// lorenzo3 is chosen when it makes the sampled data bricks more than 10% smaller: a few
// percent are not worth its cost on every read (measured on qr: +12% decompression time
// and an 8 us decode pass per 25^3 brick, for 2.5% fewer bytes). Measured on the sample
// data (whole store, lorenzo3 vs none): ta -77%, ua -61%, clw +18%, qr -2.5% at 512 x
// 512 x 150; clw +1.6%, qr -20% on the full 1429 x 1556 x 150 grid. The sampled
// estimates of the marginal cases (qr -4.1% at 512, qr -14.6% and clw -2.0% on the full
// grid) all fall on the right side of 10%, with margins of 4.6 points or more; 5% would
// leave qr at 512 within 0.9 points.
inline constexpr double kLorenzo3MinSaving = 0.10;

// Up to this many sampled bricks along x, y, z: 75 in all. Measured on the same data:
// 3 x 3 x 3 bricks estimated qr at 512 (true gain within +-2.5%) at -5.1%, 5 x 5 x 2 at
// -5.1% or -9% (4 x 4 x 2); 5 x 5 x 3 estimates it at -4.1% (-0.1% before zigzag).
inline constexpr std::array<std::size_t, 3> kPredictorSamples{5, 5, 3};

// Sampling goes layer by layer along z and stops after a layer once at least this many
// data bricks were sampled and lorenzo3 changes their size by at least this fraction
// either way: dense fields save 60-77% after the first layer, so they cost a third.
inline constexpr std::size_t kPredictorClearMinBricks = 20;
inline constexpr double kPredictorClearSaving = 0.25;

struct PredictorTrial {
  std::string variable;
  std::size_t bricks_sampled = 0;  // level-0 bricks read (fewer after a clear early stop)
  std::size_t data_bricks = 0;     // of those, the ones that store a chunk
  std::uint64_t bytes_none = 0;    // their chunk bytes without a predictor
  std::uint64_t bytes_lorenzo3 = 0;
  std::string chosen;              // "none" or "lorenzo3"
  double seconds = 0;              // reading and compressing

  double saving() const {
    return bytes_none ? 1.0 - double(bytes_lorenzo3) / double(bytes_none) : 0.0;
  }
  nlohmann::json to_json() const;
};

// The level-0 bricks sampled: along each axis with N nodes, n = min(N, per_axis[a])
// nodes at indices floor((2k + 1) N / 2n), k = 0..n-1 (evenly spread, never the domain
// edge when N > n). Depends on the grid and brick size only.
std::vector<NodeKey> predictor_sample_nodes(const OctreeLayout& layout,
                                            std::array<std::size_t, 3> per_axis);

// "lorenzo3" when bytes_lorenzo3 < (1 - kLorenzo3MinSaving) * bytes_none, else "none"
// (also when no sampled brick holds data).
std::string_view decide_predictor(std::uint64_t bytes_none, std::uint64_t bytes_lorenzo3);

// Reads the sampled bricks of time step 0 of `variable`, encodes each exactly as the
// converter would (brick kinds included) with `codec`'s Blosc settings, without and with
// lorenzo3, and decides. Uncompressed input is read as long rows through the sampled
// bricks (at most 3.5% of the variable at 5 x 5 x 3). Filtered (compressed) input, where
// every read decompresses whole chunks, samples one layer of bricks (5 x 5 x 1) read as
// one box of the whole layer: one layer of chunks decompressed, one converter slab of
// memory.
PredictorTrial choose_predictor(const ingest::InputCatalog& catalog,
                                const ingest::ScanOptions& scan, std::size_t variable,
                                const OctreeLayout& layout, const format::CodecSpec& codec);

}  // namespace strielad::build
