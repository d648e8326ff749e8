// SPDX-License-Identifier: Apache-2.0
// Moving points along a WindField from t_start to t_end (either direction):
// - kEuler: explicit Euler, fixed steps (order 1);
// - kRk4: classic Runge-Kutta, fixed steps (order 4);
// - kDopri5: Dormand-Prince 5(4), adaptive: the embedded 4th-order solution estimates
//   the error of each step; a step is accepted when the error, scaled per axis by
//   atol[axis] + rtol * |position|, has an RMS norm <= 1, else rejected and retried
//   smaller (factor 0.9 (1/err)^(1/5), between 0.2 and 5);
// - kRosenbrock: RODAS3 (Sandu et al. 1997, rosenbrock_stepper.h), linearly implicit,
//   L-stable, order 3 with an embedded order-2 estimate, adaptive like kDopri5 (factor
//   0.9 (1/err)^(1/3)); the Jacobian of the rate by finite differences every step (4 of
//   a step's 7 evaluations), 3x3 solves by LU with partial pivoting.
// Which method when (measurements in BENCHMARKS.md "Advection"):
// - The default is RK4 with 60 s steps: on wind interpolated from a grid, which has
//   kinks at every cell face, it reaches 1 m after an hour with fewer evaluations than
//   the adaptive methods on the vortex flow (1,936 against 4,324 for kDopri5 and 8,061
//   for kRosenbrock), errs by a median 2.7 cm (worst of 16: 2 m) on the sample
//   generator's wind, costs the same for every vertex (4 evaluations a step: predictable
//   frame budgets), and is exact on linear shear.
// - kDopri5 for long trajectories through smooth (analytic) fields; its error estimate
//   does not see the kinks of interpolated ones.
// - kRosenbrock for stiff flow: where the wind changes along a path faster than about
//   2.8 / step (convergence, divergence or shear above ~0.05 /s for 60 s steps: a sharp
//   front, a collapsing boundary layer, a very fine grid), every explicit method is held
//   below its stability limit (2/k for Euler, 2.8/k for RK4, k the largest rate) whatever
//   accuracy is asked for; RODAS3's step follows the accuracy only (1 m after an hour at
//   stiffness 10^4: 6,219 evaluations against 921,644 for RK4 and 1,072,192 for kDopri5).
//   Also where every trajectory must be within a bound: on the generated wind it brings
//   all 16 within 1 m with a third of RK4's evaluations. In smooth, non-stiff flow its 7
//   evaluations a step make it dearer than RK4 and kDopri5.
// A trajectory stops early, flagged, never with a NaN position:
// - kLeftDomain: the next step would leave the grid; the point is moved to within
//   min_step_s of the boundary crossing (steps halved towards it) and stays inside;
// - kMissingWind: likewise at a fill/NaN sample;
// - kStepLimit: more than max_steps steps would be needed (checked before a fixed-step
//   run starts, so nothing is half done); kStepTooSmall: the adaptive step fell below
//   min_step_s without meeting the tolerance (kRosenbrock: or without a solvable
//   I - h gamma J).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

#include "advect/wind_field.h"

namespace strielad::advect {

enum class Method { kEuler, kRk4, kDopri5, kRosenbrock };
std::string_view method_name(Method method);
// The method named by method_name. \error kInvalidArgument listing the names.
Method parse_method(std::string_view name);

enum class Stop { kReached, kLeftDomain, kMissingWind, kStepLimit, kStepTooSmall };
std::string_view stop_name(Stop stop);

struct AdvectOptions {
  Method method = Method::kRk4;
  double step_s = 60;  // fixed-step methods: the step; adaptive ones: the first trial step
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
