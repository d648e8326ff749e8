// SPDX-License-Identifier: Apache-2.0
// Wind fields sampled from formulas onto grids, for the advection tests.
#pragma once

#include <functional>

#include "advect/wind_field.h"

namespace strielad::testing {

// Sampled values of (u, v, w) at (x, y, z, t).
using WindFormula = std::function<advect::Vec3(double x, double y, double z, double t)>;

inline std::vector<double> linspace(double a, double b, std::size_t n) {
  std::vector<double> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = a + (b - a) * double(i) / double(n - 1);
  return v;
}

inline advect::WindField sample_wind(advect::WindGrid grid, double t0, double t1,
                                     const WindFormula& wind) {
  advect::WindSlice slices[2];
  for (int s = 0; s < 2; ++s) {
    const double t = s == 0 ? t0 : t1;
    for (const double z : grid.axes[2])
      for (const double y : grid.axes[1])
        for (const double x : grid.axes[0]) {
          const auto w = wind(x, y, z, t);
          slices[s].u.push_back(static_cast<float>(w[0]));
          slices[s].v.push_back(static_cast<float>(w[1]));
          slices[s].w.push_back(static_cast<float>(w[2]));
        }
  }
  return advect::WindField(std::move(grid), t0, std::move(slices[0]), t1, std::move(slices[1]));
}

}  // namespace strielad::testing
