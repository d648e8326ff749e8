// SPDX-License-Identifier: Apache-2.0
// Names the advection tests use for lib/advect's sampled wind fields.
#pragma once

#include "advect/wind_field.h"

namespace strielad::testing {

using advect::sample_wind;
inline std::vector<double> linspace(double first, double last, std::size_t n) {
  return advect::evenly_spaced(first, last, n);
}

}  // namespace strielad::testing
