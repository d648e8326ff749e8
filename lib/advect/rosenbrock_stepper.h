// SPDX-License-Identifier: Apache-2.0
// Method::kRosenbrock of advect() (integrators.h): RODAS3, the linearly implicit,
// L-stable, stiffly accurate Rosenbrock method of order 3 with an embedded order-2
// solution (4 stages, 3 new rate evaluations), from
//   A. Sandu, J. G. Verwer, J. G. Blom, E. J. Spee, G. R. Carmichael, F. A. Potra,
//   "Benchmarking stiff ODE solvers for atmospheric chemistry problems II: Rosenbrock
//   solvers", Atmospheric Environment 31(20), 3459-3472 (1997);
// the coefficients in the form of KPP's rosenbrock.f90 (subroutine Rodas3; A. Sandu,
// KPP, the Kinetic PreProcessor), which follows Hairer & Wanner, "Solving ODEs II",
// Springer 1996, section IV.7:
//   M = I - h gamma J,  gamma = 1/2,  J = d rate / d position at (p, t)
//   M K_i = h gamma (rate(t + alpha_i h, p + sum_j a_ij K_j) + sum_j c_ij / h K_j
//                    + h gamma_i d rate / dt)
//   next = p + sum_i m_i K_i,  error estimate = K_4.
// Each step differences the rate for J (one evaluation per axis, steps of
// kJacobianFraction of the grid's extent along the axis: 0.1 m on a 100 km axis, 1e-5
// degree = 1.1 m on a 10 degree one, 2 cm on a 21 km height axis) and for d rate / dt
// (one evaluation, kJacobianFraction of the time between the field's two steps, in the
// direction of integration); a difference that would leave the grid or meet fill is
// taken the other way. Those 4 evaluations are counted in AdvectResult::evaluations.
// A step costs 4 + 2 + 1 evaluations (the last, the rate at the new position, is the next
// step's first stage); a rejected one 2, as J is kept while only the step changes.
// L-stability damps what is stiff at any step, but a fast transient (a point tens of
// kilometres off a line it collapses onto at 100 /s) is still resolved to the tolerance
// in the first steps, which can take steps below the default min_step_s of 1 ms
// (kStepTooSmall): lower min_step_s for such flows.
#pragma once

#include <array>

#include "advect/integrators.h"
#include "advect/stepper_support.h"

namespace strielad::advect {

inline constexpr double kJacobianFraction = 1e-6;

using Mat3 = std::array<Vec3, 3>;  // rows

// x with m x = b, by LU with partial pivoting. False, x untouched, when m has a non-finite
// entry, a pivot is at most 1e-12 times the largest |entry| (singular to working
// precision) or x would not be finite.
bool solve_3x3(const Mat3& m, const Vec3& b, Vec3& x);

// The adaptive RODAS3 loop with the conventions of the Dormand-Prince one (integrators.h):
// step factor 0.9 (1/err)^(1/3) between 0.2 and 5, stages outside the grid or at fill
// halve the step down to min_step_s before the flagged stop, a matrix M that cannot be
// solved rejects the step and halves it (kStepTooSmall below min_step_s).
AdvectResult advect_rosenbrock(CountedField& field, const Vec3& start, double t_start,
                               double t_end, const AdvectOptions& options);

}  // namespace strielad::advect
