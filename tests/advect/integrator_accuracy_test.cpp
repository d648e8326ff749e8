// SPDX-License-Identifier: Apache-2.0
// The integrators against exact solutions: solid-body rotation (the sampled field is
// linear, so interpolation is exact and only the integrator errs), their orders of
// convergence, the adaptive pair's tolerance, time interpolation and the geographic units.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "advect/integrators.h"
#include "wind_fields.h"

namespace strielad::testing {
namespace {

using advect::Method;

constexpr double kOmega = 2 * std::numbers::pi / 3600;  // one turn an hour

advect::WindField rotation() {
  advect::WindGrid g;
  g.horizontal = advect::Horizontal::kMetres;
  g.axes = {linspace(-20000, 20000, 21), linspace(-20000, 20000, 21), linspace(0, 1000, 2)};
  return sample_wind(std::move(g), 0, 7200, [](double x, double y, double, double) {
    return Vec3{-kOmega * y, kOmega * x, 0};
  });
}

double rotation_error(Method method, double step_s, double rtol = 1e-6) {
  const auto field = rotation();
  advect::AdvectOptions o;
  o.method = method;
  o.step_s = step_s;
  o.rtol = rtol;
  o.atol = {1e-9, 1e-9, 1e-9};
  const double T = 900;  // a quarter turn: (10 km, 0) -> (0, 10 km)
  const auto r = advect::advect(field, {10000, 0, 500}, 0, T, o);
  EXPECT_EQ(r.stop, advect::Stop::kReached) << advect::method_name(method);
  const double a = kOmega * T;
  return std::hypot(r.position[0] - 10000 * std::cos(a), r.position[1] - 10000 * std::sin(a));
}

TEST(IntegratorAccuracyTest, EulerConvergesAtFirstOrder) {
  const double coarse = rotation_error(Method::kEuler, 30), fine = rotation_error(Method::kEuler, 15);
  EXPECT_NEAR(coarse / fine, 2.0, 0.2);
}

TEST(IntegratorAccuracyTest, Rk4ConvergesAtFourthOrder) {
  const double coarse = rotation_error(Method::kRk4, 300), fine = rotation_error(Method::kRk4, 150);
  EXPECT_NEAR(coarse / fine, 16.0, 2.0);
  EXPECT_LT(rotation_error(Method::kRk4, 60), 0.05);  // metres after 15 minutes (h^4 truncation)
}

TEST(IntegratorAccuracyTest, Dopri5MeetsItsToleranceAndTighterCostsMore) {
  const auto field = rotation();
  advect::AdvectOptions loose, tight;
  loose.method = tight.method = Method::kDopri5;
  loose.rtol = 1e-4;
  tight.rtol = 1e-9;
  loose.atol = {1e-3, 1e-3, 1e-3};
  tight.atol = {1e-8, 1e-8, 1e-8};
  const auto a = advect::advect(field, {10000, 0, 500}, 0, 900, loose);
  const auto b = advect::advect(field, {10000, 0, 500}, 0, 900, tight);
  const double angle = kOmega * 900;
  const auto error = [&](const advect::AdvectResult& r) {
    return std::hypot(r.position[0] - 10000 * std::cos(angle), r.position[1] - 10000 * std::sin(angle));
  };
  EXPECT_LT(error(a), 10.0);  // rtol 1e-4 of 10 km is 1 m per step
  EXPECT_LT(error(b), 1e-3);
  EXPECT_LT(error(b), error(a));
  EXPECT_GT(b.evaluations, a.evaluations);
  EXPECT_EQ(b.t, 900);
}

TEST(IntegratorAccuracyTest, BackwardIntegrationReturnsToTheStart) {
  const auto field = rotation();
  advect::AdvectOptions o;
  o.method = Method::kDopri5;
  o.rtol = 1e-10;
  o.atol = {1e-8, 1e-8, 1e-8};
  const auto forward = advect::advect(field, {10000, 0, 500}, 0, 600, o);
  const auto back = advect::advect(field, forward.position, 600, 0, o);
  EXPECT_EQ(back.stop, advect::Stop::kReached);
  EXPECT_NEAR(back.position[0], 10000, 1e-3);
  EXPECT_NEAR(back.position[1], 0, 1e-3);
}

TEST(IntegratorAccuracyTest, WindLinearInTimeIsIntegratedExactlyByRk4) {
  // u grows from 0 to 10 m/s over the 3600 s between the steps: x(T) = 5 T^2 / 3600.
  const auto field = testing::wind_growing_in_time();
  advect::AdvectOptions o;
  o.method = Method::kRk4;
  o.step_s = 600;
  const auto r = advect::advect(field, {1000, 500000, 500}, 0, 3600, o);
  EXPECT_NEAR(r.position[0], 1000 + 5 * 3600.0, 1e-6);
  EXPECT_EQ(r.evaluations, 1u + 6u * 4u);  // the start, then 4 per step (the end point is the next k1)
}

TEST(IntegratorAccuracyTest, UniformZonalWindMovesLongitudeByTheArcLength) {
  advect::WindGrid g;
  g.axes = {linspace(0, 20, 11), linspace(40, 50, 11), linspace(0, 12000, 4)};
  const auto field = sample_wind(std::move(g), 0, 3600, [](double, double, double, double) {
    return Vec3{20, 0, 0};
  });
  // Along a parallel the latitude stays 45 degrees, so dlon/dt is constant.
  const auto r = advect::advect(field, {5, 45, 3000}, 0, 3600);
  const double deg = 180 / std::numbers::pi;
  EXPECT_NEAR(r.position[0], 5 + 20 * 3600 / (advect::kEarthRadiusM * std::cos(45 / deg)) * deg, 1e-7);
  EXPECT_NEAR(r.position[1], 45, 1e-12);
  EXPECT_EQ(r.position[2], 3000);
}

}  // namespace
}  // namespace strielad::testing
