// SPDX-License-Identifier: Apache-2.0
// RODAS3 (Method::kRosenbrock) against exact solutions on smooth fields: its local error
// shrinks with the fourth power of the step (order 3), the error falls with the cube of
// the work, the tolerance is met, wind that changes in time is followed (the d rate / dt
// term), and integrating back returns to the start.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "advect/integrators.h"
#include "wind_fields.h"

namespace strielad::testing {
namespace {

using advect::Method;

constexpr double kOmega = 2 * std::numbers::pi / 3600;  // one turn an hour
constexpr double kRadius = 10000;

advect::WindField rotation() {
  advect::WindGrid g;
  g.horizontal = advect::Horizontal::kMetres;
  g.axes = {linspace(-20000, 20000, 21), linspace(-20000, 20000, 21), linspace(0, 1000, 2)};
  return sample_wind(std::move(g), 0, 7200, [](double x, double y, double, double) {
    return Vec3{-kOmega * y, kOmega * x, 0};
  });
}

double distance_from_exact(const advect::AdvectResult& r, double t) {
  const double a = kOmega * t;
  return std::hypot(r.position[0] - kRadius * std::cos(a), r.position[1] - kRadius * std::sin(a));
}

advect::AdvectOptions rosenbrock(double rtol, double atol) {
  advect::AdvectOptions o;
  o.method = Method::kRosenbrock;
  o.rtol = rtol;
  o.atol = {atol, atol, atol};
  return o;
}

// One step of h (the first trial step is the whole span; a huge tolerance accepts it).
double one_step_error(double h) {
  auto o = rosenbrock(1, 1e9);
  o.step_s = h;
  const auto r = advect::advect(rotation(), {kRadius, 0, 500}, 0, h, o);
  EXPECT_EQ(r.accepted, 1u);
  EXPECT_EQ(r.rejected, 0u);
  EXPECT_EQ(r.evaluations, 1u + 7u);  // the start, then J (3 + 1) and 3 new rates
  return distance_from_exact(r, h);
}

TEST(RosenbrockAccuracyTest, LocalErrorShrinksWithTheFourthPowerOfTheStep) {
  const double coarse = one_step_error(300), fine = one_step_error(150);
  EXPECT_GT(coarse, 1.0);  // far above the float32 sampling noise (~1e-3 m)
  EXPECT_NEAR(coarse / fine, 16.0, 2.5);
}

TEST(RosenbrockAccuracyTest, ErrorFallsWithTheCubeOfTheWork) {
  const auto field = rotation();
  const auto loose = advect::advect(field, {kRadius, 0, 500}, 0, 900, rosenbrock(1e-4, 1e-9));
  const auto tight = advect::advect(field, {kRadius, 0, 500}, 0, 900, rosenbrock(1e-7, 1e-9));
  const double order = std::log(distance_from_exact(loose, 900) / distance_from_exact(tight, 900)) /
                       std::log(double(tight.evaluations) / double(loose.evaluations));
  EXPECT_NEAR(order, 3.0, 0.5);
}

TEST(RosenbrockAccuracyTest, MeetsItsToleranceAndTighterCostsMore) {
  const auto field = rotation();
  const auto a = advect::advect(field, {kRadius, 0, 500}, 0, 900, rosenbrock(1e-4, 1e-3));
  const auto b = advect::advect(field, {kRadius, 0, 500}, 0, 900, rosenbrock(1e-7, 1e-6));
  EXPECT_EQ(b.stop, advect::Stop::kReached);
  EXPECT_EQ(b.t, 900);
  EXPECT_LT(distance_from_exact(a, 900), 10.0);  // rtol 1e-4 of 10 km is 1 m per step
  EXPECT_LT(distance_from_exact(b, 900), 0.01);
  EXPECT_LT(distance_from_exact(b, 900), distance_from_exact(a, 900));
  EXPECT_GT(b.evaluations, a.evaluations);
}

TEST(RosenbrockAccuracyTest, BackwardIntegrationReturnsToTheStart) {
  const auto field = rotation();
  const auto o = rosenbrock(1e-9, 1e-8);
  const auto forward = advect::advect(field, {kRadius, 0, 500}, 0, 600, o);
  const auto back = advect::advect(field, forward.position, 600, 0, o);
  EXPECT_EQ(back.stop, advect::Stop::kReached);
  EXPECT_EQ(back.t, 0);
  EXPECT_NEAR(back.position[0], kRadius, 1e-3);
  EXPECT_NEAR(back.position[1], 0, 1e-3);
}

TEST(RosenbrockAccuracyTest, WindChangingInTimeIsFollowed) {
  // u grows from 0 to 10 m/s over the hour between the steps: x(T) = 5 T^2 / 3600. Only
  // the d rate / dt term carries this: the Jacobian is zero.
  const auto field = testing::wind_growing_in_time();
  auto o = rosenbrock(1, 1e9);  // every step accepted: 600 s, then growing
  o.step_s = 600;
  const auto r = advect::advect(field, {1000, 500000, 500}, 0, 3600, o);
  EXPECT_EQ(r.stop, advect::Stop::kReached);
  EXPECT_NEAR(r.position[0], 1000 + 5 * 3600.0, 1e-3);  // differencing d rate / dt rounds
  // Backwards from the end the same path is retraced.
  const auto back = advect::advect(field, r.position, 3600, 0, o);
  EXPECT_NEAR(back.position[0], 1000, 1e-3);
}

}  // namespace
}  // namespace strielad::testing
