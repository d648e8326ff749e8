// SPDX-License-Identifier: Apache-2.0
// Stiff flow: convergence towards the line y = 50 km at k = 10 /s while x relaxes at
// 1e-3 /s (stiffness ratio 1e4). The explicit methods are bound to steps below ~2.8/k;
// RODAS3 (L-stable) takes steps a hundred times longer and reaches a metre with a few
// hundred evaluations, where RK4 just past its limit is off by kilometres and the
// adaptive Dormand-Prince pair needs tens of thousands.
#include <gtest/gtest.h>

#include <cmath>

#include "advect/integrators.h"
#include "wind_fields.h"

namespace strielad::testing {
namespace {

using advect::Method;

constexpr double kSlow = 1e-3, kX0 = 50e3, kY0 = 50e3, kHour = 3600;

advect::WindField converging(double k) {
  advect::WindGrid g;
  g.horizontal = advect::Horizontal::kMetres;
  g.axes = {linspace(0, 100e3, 21), linspace(0, 100e3, 21), linspace(0, 1e3, 2)};
  return sample_wind(std::move(g), 0, 7200, [k](double x, double y, double, double) {
    return Vec3{-kSlow * (x - kX0), -k * (y - kY0), 0};
  });
}

double error_after_an_hour(double k, const Vec3& start, const advect::AdvectResult& r) {
  const double x = kX0 + (start[0] - kX0) * std::exp(-kSlow * kHour);
  const double y = kY0 + (start[1] - kY0) * std::exp(-k * kHour);
  return std::hypot(r.position[0] - x, r.position[1] - y, r.position[2] - start[2]);
}

advect::AdvectOptions rosenbrock(double rtol) {
  advect::AdvectOptions o;
  o.method = Method::kRosenbrock;
  o.rtol = rtol;
  o.atol = {1e-3, 1e-3, 1e-3};
  return o;
}

TEST(RosenbrockStiffTest, StiffnessRatio1e4NeedsNoStepsBelowTheExplicitLimit) {
  constexpr double k = 10;
  const auto field = converging(k);
  const Vec3 start{80e3, 20e3, 500};  // 30 km from the line it collapses onto
  const auto r = advect::advect(field, start, 0, kHour, rosenbrock(1e-5));
  ASSERT_EQ(r.stop, advect::Stop::kReached);
  EXPECT_LT(error_after_an_hour(k, start, r), 1.0);
  EXPECT_LT(r.evaluations, 1500u);
  // The mean step is a hundred times RK4's stability limit (2.8/k = 0.28 s).
  EXPECT_GT(kHour / double(r.accepted), 100 * 0.28);
}

TEST(RosenbrockStiffTest, ExplicitMethodsNeedFarMoreForTheSameAccuracy) {
  constexpr double k = 10;
  const auto field = converging(k);
  const Vec3 start{80e3, 20e3, 500};
  const auto implicit = advect::advect(field, start, 0, kHour, rosenbrock(1e-5));
  // RK4 with a step just past its stability limit is off by kilometres...
  const auto unstable = advect::advect(
      field, start, 0, kHour, {.method = Method::kRk4, .step_s = 3.0 / k, .max_steps = 100'000});
  EXPECT_GT(error_after_an_hour(k, start, unstable), 1000.0);
  // ...and Dormand-Prince at the same tolerance, stable, pays for it in evaluations.
  advect::AdvectOptions dopri = rosenbrock(1e-5);
  dopri.method = Method::kDopri5;
  const auto adaptive = advect::advect(field, start, 0, kHour, dopri);
  EXPECT_LT(error_after_an_hour(k, start, adaptive), 1.0);
  EXPECT_GT(adaptive.evaluations, 50 * implicit.evaluations);
}

TEST(RosenbrockStiffTest, CostDoesNotGrowWithTheStiffness) {
  const Vec3 start{80e3, 20e3, 500};
  std::uint64_t evaluations[2];
  int i = 0;
  for (const double k : {1.0, 100.0}) {
    // The first steps resolve the collapse onto the line (30 km at 3,000 km/s when
    // k = 100) to the tolerance: that needs steps below the default 1 ms minimum.
    auto o = rosenbrock(1e-6);
    o.min_step_s = 1e-6;
    const auto r = advect::advect(converging(k), start, 0, kHour, o);
    ASSERT_EQ(r.stop, advect::Stop::kReached) << k;
    EXPECT_LT(error_after_an_hour(k, start, r), 0.1) << k;
    evaluations[i++] = r.evaluations;
  }
  // A hundred times stiffer: at most 1.5 times the work (explicit: a hundred times).
  EXPECT_LT(double(evaluations[1]), 1.5 * double(evaluations[0]));
}

}  // namespace
}  // namespace strielad::testing
