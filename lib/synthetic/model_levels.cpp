// SPDX-License-Identifier: Apache-2.0
#include "synthetic/model_levels.h"

#include <algorithm>
#include <cmath>

#include "synthetic/atmosphere_profiles.h"
#include "synthetic/sample_grid.h"

namespace strielad::synthetic {
namespace {

// nz + 1 nominal half-level heights, kModelTop down to 0, spaced like stretched_heights.
std::vector<double> nominal_half_heights(std::size_t nz) {
  std::vector<double> h(nz + 1);
  const double denom = std::expm1(kHeightStretch);
  for (std::size_t k = 0; k <= nz; ++k) {
    const double s = static_cast<double>(nz - k) / static_cast<double>(nz);
    h[k] = kModelTop * std::expm1(kHeightStretch * s) / denom;
  }
  h.front() = kModelTop;
  h.back() = 0.0;
  return h;
}

std::vector<double> midpoints(const std::vector<double>& half) {
  std::vector<double> full(half.size() - 1);
  for (std::size_t k = 0; k < full.size(); ++k) full[k] = 0.5 * (half[k] + half[k + 1]);
  return full;
}

}  // namespace

HybridHeightLevels hybrid_height_levels(std::size_t nz) {
  HybridHeightLevels levels;
  levels.half_a = nominal_half_heights(nz);
  levels.half_b.resize(nz + 1);
  const double top = std::sinh(kModelTop / kSleveDecayHeight);
  for (std::size_t k = 0; k <= nz; ++k) {
    levels.half_b[k] = std::sinh((kModelTop - levels.half_a[k]) / kSleveDecayHeight) / top;
  }
  levels.half_b.front() = 0.0;
  levels.half_b.back() = 1.0;
  levels.full_a = midpoints(levels.half_a);
  levels.full_b = midpoints(levels.half_b);
  return levels;
}

HybridPressureLevels hybrid_pressure_levels(std::size_t nz) {
  HybridPressureLevels levels;
  const std::vector<double> h = nominal_half_heights(nz);
  const double eta_top = column_pressure(kModelTop, 1.0, 0.0);
  levels.half_ap.resize(nz + 1);
  levels.half_b.resize(nz + 1);
  for (std::size_t k = 0; k <= nz; ++k) {
    const double eta = k == nz ? 1.0 : column_pressure(h[k], 1.0, 0.0);
    const double t = std::clamp((eta - eta_top) / (1.0 - eta_top), 0.0, 1.0);
    const double b = t * std::sqrt(t);
    levels.half_b[k] = b;
    levels.half_ap[k] = k == nz ? 0.0 : kHybridReferencePressure * (eta - b);
  }
  levels.full_ap = midpoints(levels.half_ap);
  levels.full_b = midpoints(levels.half_b);
  return levels;
}

}  // namespace strielad::synthetic
