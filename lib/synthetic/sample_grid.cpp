// SPDX-License-Identifier: Apache-2.0
#include "synthetic/sample_grid.h"

#include <cmath>
#include <numbers>

namespace strielad::synthetic {
namespace {

constexpr double kKmPerDegree = 111.32;
constexpr double kLonCentre = 0.5 * (kLonMin + kLonMax);
constexpr double kLatCentre = 0.5 * (kLatMin + kLatMax);

}  // namespace

std::vector<double> uniform_axis(std::size_t n, double lo, double hi) {
  std::vector<double> values(n);
  if (n == 1) {
    values[0] = 0.5 * (lo + hi);
    return values;
  }
  for (std::size_t i = 0; i < n; ++i) {
    values[i] = lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(n - 1);
  }
  values[n - 1] = hi;
  return values;
}

std::vector<double> stretched_heights(std::size_t n) {
  std::vector<double> z(n);
  const double denom = std::expm1(kHeightStretch);
  for (std::size_t k = 0; k < n; ++k) {
    // s runs from 1 at the top (k = 0) to 0 at the bottom (k = n - 1).
    const double s =
        n == 1 ? 0.0 : static_cast<double>(n - 1 - k) / static_cast<double>(n - 1);
    z[k] = kLowestLevel + (kModelTop - kLowestLevel) * std::expm1(kHeightStretch * s) / denom;
  }
  if (n > 1) {
    z.front() = kModelTop;
    z.back() = kLowestLevel;
  }
  return z;
}

SampleGrid::SampleGrid(Dims3 d)
    : dims(d),
      lon(uniform_axis(d.x, kLonMin, kLonMax)),
      lat(uniform_axis(d.y, kLatMin, kLatMax)),
      height(stretched_heights(d.z)),
      x_km(d.x),
      y_km(d.y) {
  const double cos_lat = std::cos(kLatCentre * std::numbers::pi / 180.0);
  for (std::size_t i = 0; i < d.x; ++i) x_km[i] = (lon[i] - kLonCentre) * kKmPerDegree * cos_lat;
  for (std::size_t j = 0; j < d.y; ++j) y_km[j] = (lat[j] - kLatCentre) * kKmPerDegree;
}

}  // namespace strielad::synthetic
