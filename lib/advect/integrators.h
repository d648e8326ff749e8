// SPDX-License-Identifier: Apache-2.0
// Moving points along a WindField from t_start to t_end (either direction):
// - kEuler: explicit Euler, fixed steps (order 1);
// - kRk4: classic Runge-Kutta, fixed steps (order 4);
// - kDopri5: Dormand-Prince 5(4), adaptive: the embedded 4th-order solution estimates
//   the error of each step; a step is accepted when the error, scaled per axis by
//   atol[axis] + rtol * |position|, has an RMS norm <= 1, else rejected and retried
//   smaller (factor 0.9 (1/err)^(1/5), between 0.2 and 5).
// The default is RK4 with 60 s steps (BENCHMARKS.md "Advection"): on wind interpolated
// from a grid, which has kinks at every cell face, it reaches 1 m after an hour with
// fewer evaluations than the adaptive pair (1,936 against 4,324 on the vortex flow),
// costs the same for every vertex (4 evaluations a step: predictable frame budgets), and
// is exact on linear shear. Choose kDopri5 for long trajectories through smooth fields.
// A trajectory stops early, flagged, never with a NaN position:
// - kLeftDomain: the next step would leave the grid; the point is moved to within
//   min_step_s of the boundary crossing (steps halved towards it) and stays inside;
// - kMissingWind: likewise at a fill/NaN sample;
// - kStepLimit: more than max_steps steps would be needed (checked before a fixed-step
//   run starts, so nothing is half done); kStepTooSmall: the adaptive step fell below
//   min_step_s without meeting the tolerance.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "advect/wind_field.h"

namespace strielad::advect {

enum class Method { kEuler, kRk4, kDopri5 };
std::string_view method_name(Method method);

enum class Stop { kReached, kLeftDomain, kMissingWind, kStepLimit, kStepTooSmall };
std::string_view stop_name(Stop stop);

struct AdvectOptions {
  Method method = Method::kRk4;
  double step_s = 60;  // fixed-step methods: the step; kDopri5: the first trial step
  double rtol = 1e-6;
  // Absolute tolerance per axis, in axis units: 1e-6 degree is 0.11 m; 0.1 m or 1 Pa.
  Vec3 atol{1e-6, 1e-6, 0.1};
  std::uint64_t max_steps = 1'000'000;
  double min_step_s = 1e-3;
};

struct AdvectResult {
  Vec3 position{};
  double t = 0;  // where the trajectory ended (t_end when kReached)
  Stop stop = Stop::kReached;
  std::uint64_t evaluations = 0;  // wind field evaluations
  std::uint64_t accepted = 0, rejected = 0;
};

// \error kInvalidArgument for non-finite times or start, a step or tolerance that is
// not finite and > 0.
AdvectResult advect(const WindField& field, const Vec3& start, double t_start, double t_end,
                    const AdvectOptions& options = {});

}  // namespace strielad::advect
