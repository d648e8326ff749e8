// SPDX-License-Identifier: Apache-2.0
// The 3x3 solve of the Rosenbrock stages (solve_3x3): exact where it must pivot, and a
// refusal, never a NaN or Inf, for singular, nearly singular and non-finite matrices;
// and a flow whose I - h gamma J is singular at the first trial step still ends finite.
#include <gtest/gtest.h>

#include <cmath>

#include "advect/integrators.h"
#include "advect/rosenbrock_stepper.h"
#include "wind_fields.h"

namespace strielad::testing {
namespace {

using advect::Mat3;

TEST(RosenbrockLinearSolveTest, PivotsPastAZeroLeadingEntry) {
  const Mat3 m{Vec3{0, 2, 1}, Vec3{1, 0, 0}, Vec3{0, 1, 3}};
  const Vec3 x_true{1.5, -2, 0.25};
  Vec3 b{};
  for (int i = 0; i < 3; ++i) {
    b[i] = m[i][0] * x_true[0] + m[i][1] * x_true[1] + m[i][2] * x_true[2];
  }
  Vec3 x{};
  ASSERT_TRUE(advect::solve_3x3(m, b, x));
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(x[i], x_true[i], 1e-14);
}

TEST(RosenbrockLinearSolveTest, SingularAndNonFiniteMatricesAreRefused) {
  const Vec3 b{1, 2, 3};
  Vec3 x{7, 7, 7};
  EXPECT_FALSE(advect::solve_3x3(Mat3{Vec3{1, 2, 3}, Vec3{2, 4, 6}, Vec3{0, 1, 1}}, b, x));
  EXPECT_FALSE(advect::solve_3x3(Mat3{Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1e-15}}, b, x));
  EXPECT_FALSE(advect::solve_3x3(Mat3{Vec3{1, 0, 0}, Vec3{0, NAN, 0}, Vec3{0, 0, 1}}, b, x));
  EXPECT_FALSE(advect::solve_3x3(Mat3{Vec3{INFINITY, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}, b, x));
  EXPECT_FALSE(advect::solve_3x3(Mat3{}, b, x));
  EXPECT_EQ(x, (Vec3{7, 7, 7}));  // untouched on refusal
  // A well-conditioned but badly scaled matrix is solved.
  EXPECT_TRUE(advect::solve_3x3(Mat3{Vec3{1e-9, 0, 0}, Vec3{0, 1e-9, 0}, Vec3{0, 0, 1e-9}}, b, x));
  EXPECT_NEAR(x[2], 3e9, 1e-3);
}

TEST(RosenbrockLinearSolveTest, SingularStageMatrixRejectsTheStepAndStaysFinite) {
  // Diverging wind u = s (x - 50 km) with s = 1/30 /s: J = diag(s, 0, 0), so
  // I - h gamma J is singular for h = 2/s = 60 s, the first trial step.
  constexpr double s = 1.0 / 30;
  advect::WindGrid g;
  g.horizontal = advect::Horizontal::kMetres;
  g.axes = {linspace(0, 100e3, 101), linspace(0, 10e3, 3), linspace(0, 1e3, 2)};
  const auto field = sample_wind(std::move(g), 0, 3600, [](double x, double, double, double) {
    return Vec3{s * (x - 50e3), 0, 0};
  });
  advect::AdvectOptions o;
  o.method = advect::Method::kRosenbrock;
  o.step_s = 60;
  o.rtol = 1e-8;
  o.atol = {1e-4, 1e-4, 1e-4};
  const auto r = advect::advect(field, {50e3 + 10, 5e3, 500}, 0, 60, o);
  for (const double c : r.position) EXPECT_TRUE(std::isfinite(c));
  ASSERT_EQ(r.stop, advect::Stop::kReached);
  EXPECT_GE(r.rejected, 1u);
  EXPECT_NEAR(r.position[0], 50e3 + 10 * std::exp(s * 60), 0.01);  // rtol 1e-8 of 50 km per step
}

}  // namespace
}  // namespace strielad::testing
