// SPDX-License-Identifier: Apache-2.0
// What the steppers of integrators.cpp and rosenbrock_stepper.cpp share: the wind field
// with a count of its evaluations (what the work-precision diagrams plot), the stop that
// a failed evaluation means, and the scaled error norm of the adaptive methods.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "advect/integrators.h"
#include "advect/wind_field.h"

namespace strielad::advect {

struct CountedField {
  const WindField& wind;
  std::uint64_t evaluations = 0;
  Sample rate(const Vec3& p, double t, Vec3& out) {
    ++evaluations;
    return wind.rate(p, t, out);
  }
  bool inside(const Vec3& p) const { return wind.inside(p); }
};

inline Stop stop_for(Sample s) {
  return s == Sample::kMissing ? Stop::kMissingWind : Stop::kLeftDomain;
}

// RMS over the axes of the local error estimate scaled by atol[axis] + rtol * |position|
// (the larger of the step's start and end): a step is accepted when this is <= 1.
inline double scaled_error(const Vec3& error, const Vec3& from, const Vec3& to,
                           const AdvectOptions& o) {
  double sum = 0;
  for (int a = 0; a < 3; ++a) {
    const double scale = o.atol[a] + o.rtol * std::max(std::abs(from[a]), std::abs(to[a]));
    sum += (error[a] / scale) * (error[a] / scale);
  }
  return std::sqrt(sum / 3);
}

}  // namespace strielad::advect
