// SPDX-License-Identifier: Apache-2.0
// Order statistics of a set of measurements: percentiles (linear interpolation between
// closest ranks, like numpy's default), median, mean and spread.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace strielad::bench {

struct Summary {
  std::size_t count = 0;
  double min = 0, p50 = 0, p90 = 0, p99 = 0, max = 0, mean = 0;
};

// q in [0, 1]; `sorted` ascending and not empty.
double percentile_sorted(std::span<const double> sorted, double q);

// Median of the values (0 for none).
double median(std::vector<double> values);

// Summary of the values (all zero for none).
Summary summarize(std::vector<double> values);

}  // namespace strielad::bench
