// SPDX-License-Identifier: Apache-2.0
// What a store converted from a robustness case must hold, computed from the case's
// input without lib/convert: the level-0 values (the source value after CF decoding in the
// store's type, NaN where missing), every node's exact statistics (formats/store.md,
// "Per-node statistics"), and the sub-sampling of one level into the next
// (formats/store.md, "Octree") with fallback means in extended precision.
//
// Documented accuracy of a fallback mean (docs/robustness.md, "Sums and means"): the
// converter sums the k <= 27 valid neighbours in double and divides by k, then rounds to
// the variable's type T, so
//   |stored - exact mean| <= ulp_T(exact mean) / 2 + (k + 1) * 2^-53 * (sum |v_i|) / k,
// and never overflows (a sum beyond the double range is taken again on scaled values).
// The reference mean is a compensated (Neumaier) sum in long double.
#pragma once

#include <cstdint>
#include <vector>

#include "octree/octree_layout.h"
#include "robust/extreme_case.h"

namespace strielad::robust {

// Whether the store keeps the case's variable as float64 (else float32).
bool stores_double(const ExtremeCase& c);

// Level-0 values per step (x fastest), as the store must hold them. Empty when the case
// declares its variable without values.
std::vector<std::vector<double>> reference_level0(const ExtremeCase& c);

struct NodeReference {
  double min = 0, max = 0;  // NaN when no covered sample is valid
  std::uint64_t valid_count = 0;
};

// Every node's statistics for one step's level-0 values.
std::vector<NodeReference> reference_node_stats(const OctreeLayout& layout,
                                                const std::vector<double>& level0);

// Widens the ranges of the nodes of `level` (> 0) to their own samples (`values`: the
// whole level, x fastest), as formats/store.md, "Per-node statistics" has it for nodes
// above level 0.
void widen_to_level_samples(std::vector<NodeReference>& stats, const OctreeLayout& layout,
                            std::size_t level, const std::vector<double>& values);

struct CoarseReference {
  std::vector<double> values;     // level L+1, rounded to the store type (NaN = missing)
  std::vector<long double> exact;  // the exact value (a fallback mean before rounding)
  std::vector<double> tolerance;  // per sample: 0 = bit-exact (a valid centre taken as is)
  std::vector<std::uint8_t> fallback;  // 1 where the sample is a mean of neighbours
};

// Sub-samples level `fine_level` (its samples as the store holds them) into the next
// level by the rule of formats/store.md, independently of lib/convert.
CoarseReference reference_downsample(const OctreeLayout& layout, std::size_t fine_level,
                                     const std::vector<double>& fine, bool is_double);

// The documented bound above for a mean of `count` values with sum of magnitudes
// `sum_abs`, whose exact value is `exact`, stored as float32 or float64.
double mean_tolerance(long double exact, long double sum_abs, std::size_t count, bool is_double);

}  // namespace strielad::robust
