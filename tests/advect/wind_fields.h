// SPDX-License-Identifier: Apache-2.0
// Names the advection tests use for lib/advect's sampled wind fields.
#pragma once

#include "advect/wind_field.h"

namespace strielad::testing {

using advect::sample_wind;
inline std::vector<double> linspace(double first, double last, std::size_t n) {
  return advect::evenly_spaced(first, last, n);
}

// Uniform eastward wind growing from 0 to 10 m/s over the hour between the two steps,
// on a metric grid 1000 km wide and 1 km deep: x(T) = x0 + 5 T^2 / 3600 m.
inline advect::WindField wind_growing_in_time() {
  advect::WindGrid g;
  g.horizontal = advect::Horizontal::kMetres;
  g.axes = {linspace(0, 1e6, 3), linspace(0, 1e6, 3), linspace(0, 1000, 2)};
  return advect::sample_wind(std::move(g), 0, 3600, [](double, double, double, double t) {
    return Vec3{10 * t / 3600, 0, 0};
  });
}

}  // namespace strielad::testing
