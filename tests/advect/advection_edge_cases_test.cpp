// SPDX-License-Identifier: Apache-2.0
// Trajectories that cannot go on stop flagged, inside the domain, never with a NaN
// position: leaving the domain (sideways, through the top with strong vertical wind and
// backwards in time), fill in the wind, zero wind, the pole, tiny, zero and huge time
// spans, bad arguments. Every integrator, Rosenbrock included.
#include <gtest/gtest.h>

#include <cmath>

#include "advect/integrators.h"
#include "core/error.h"
#include "wind_fields.h"

namespace strielad::testing {
namespace {

using advect::Method;
using advect::Stop;

advect::WindField uniform(Vec3 wind) {
  advect::WindGrid g;
  g.horizontal = advect::Horizontal::kMetres;
  g.axes = {linspace(0, 10000, 11), linspace(0, 10000, 11), linspace(0, 10000, 11)};
  return sample_wind(std::move(g), 0, 3600, [wind](double, double, double, double) { return wind; });
}

void expect_finite_inside(const advect::WindField& field, const advect::AdvectResult& r) {
  for (const double c : r.position) EXPECT_TRUE(std::isfinite(c));
  EXPECT_TRUE(field.inside(r.position));
}

TEST(AdvectionEdgeCasesTest, LeavingTheDomainStopsAtItsBoundaryFlagged) {
  const auto field = uniform({10, 0, 0});  // 10 m/s east: the east edge after 900 s from x = 1000
  for (const Method m : {Method::kEuler, Method::kRk4, Method::kDopri5, Method::kRosenbrock}) {
    const auto r = advect::advect(field, {1000, 5000, 5000}, 0, 3600, {.method = m, .step_s = 60});
    EXPECT_EQ(r.stop, Stop::kLeftDomain) << advect::method_name(m);
    expect_finite_inside(field, r);
    EXPECT_NEAR(r.position[0], 10000, 0.1) << advect::method_name(m);
    EXPECT_NEAR(r.t, 900, 0.01) << advect::method_name(m);
  }
}

TEST(AdvectionEdgeCasesTest, StrongVerticalWindLeavesThroughTheTop) {
  const auto field = uniform({0, 0, 50});  // 50 m/s up: the top (10 km) after 180 s
  for (const Method m : {Method::kDopri5, Method::kRosenbrock}) {
    const auto r = advect::advect(field, {5000, 5000, 1000}, 0, 3600, {.method = m});
    EXPECT_EQ(r.stop, Stop::kLeftDomain) << advect::method_name(m);
    expect_finite_inside(field, r);
    EXPECT_NEAR(r.position[2], 10000, 0.1) << advect::method_name(m);
  }
}

TEST(AdvectionEdgeCasesTest, LeavingTheDomainBackwardsInTimeStopsFlagged) {
  const auto field = uniform({10, 0, 0});  // backwards the point moves west: x = 0 at t = 2700
  for (const Method m : {Method::kRk4, Method::kDopri5, Method::kRosenbrock}) {
    const auto r = advect::advect(field, {9000, 5000, 5000}, 3600, 0, {.method = m, .step_s = 60});
    EXPECT_EQ(r.stop, Stop::kLeftDomain) << advect::method_name(m);
    expect_finite_inside(field, r);
    EXPECT_NEAR(r.position[0], 0, 0.1) << advect::method_name(m);
    EXPECT_NEAR(r.t, 2700, 0.01) << advect::method_name(m);
  }
}

TEST(AdvectionEdgeCasesTest, FillInTheWindStopsBeforeIt) {
  advect::WindGrid g;
  g.horizontal = advect::Horizontal::kMetres;
  g.axes = {linspace(0, 10000, 11), linspace(0, 10000, 11), linspace(0, 10000, 11)};
  const auto field = sample_wind(std::move(g), 0, 3600, [](double x, double, double, double) {
    return Vec3{x >= 6000 ? std::nan("") : 10.0, 0, 0};
  });
  for (const Method m : {Method::kEuler, Method::kRk4, Method::kDopri5, Method::kRosenbrock}) {
    const auto r = advect::advect(field, {1000, 5000, 5000}, 0, 3600, {.method = m, .step_s = 60});
    EXPECT_EQ(r.stop, Stop::kMissingWind) << advect::method_name(m);
    expect_finite_inside(field, r);
    // The cells touching x = 6000 (from x = 5000) have no wind.
    EXPECT_NEAR(r.position[0], 5000, 1.0) << advect::method_name(m);
  }
}

TEST(AdvectionEdgeCasesTest, ZeroWindKeepsThePointWhereItIs) {
  const auto field = uniform({0, 0, 0});
  const auto r = advect::advect(field, {1234, 5678, 910}, 0, 3600);
  EXPECT_EQ(r.stop, Stop::kReached);
  EXPECT_EQ(r.position, (Vec3{1234, 5678, 910}));
  for (const Method m : {Method::kDopri5, Method::kRosenbrock}) {
    const auto adaptive = advect::advect(field, {1234, 5678, 910}, 0, 3600, {.method = m});
    EXPECT_EQ(adaptive.position, (Vec3{1234, 5678, 910})) << advect::method_name(m);
    EXPECT_LT(adaptive.evaluations, 50u) << advect::method_name(m);  // the step grows at once
  }
}

TEST(AdvectionEdgeCasesTest, AtThePoleThePositionStaysFinite) {
  advect::WindGrid g;
  g.axes = {linspace(-180, 180, 37), linspace(80, 90, 11), linspace(0, 1000, 2)};
  const auto field = sample_wind(std::move(g), 0, 3600, [](double, double, double, double) {
    return Vec3{10, 0, 0};
  });
  for (const Method m : {Method::kEuler, Method::kRk4, Method::kDopri5, Method::kRosenbrock}) {
    const auto r = advect::advect(field, {0, 89.9999, 500}, 0, 3600, {.method = m});
    expect_finite_inside(field, r);
    EXPECT_NE(r.stop, Stop::kReached) << advect::method_name(m);
  }
  const auto r = advect::advect(field, {0, 89.9999, 500}, 0, 3600);
  expect_finite_inside(field, r);
  // Flagged one way or another (longitude runs out of the axis), never NaN.
  EXPECT_NE(r.stop, Stop::kReached);
}

TEST(AdvectionEdgeCasesTest, TinyZeroAndHugeSpans) {
  const auto field = uniform({1, 2, 0.5});
  const auto zero = advect::advect(field, {100, 100, 100}, 10, 10);
  EXPECT_EQ(zero.stop, Stop::kReached);
  EXPECT_EQ(zero.position, (Vec3{100, 100, 100}));
  EXPECT_EQ(zero.evaluations, 0u);
  const auto tiny = advect::advect(field, {100, 100, 100}, 10, 10 + 1e-9);
  EXPECT_EQ(tiny.stop, Stop::kReached);
  EXPECT_NEAR(tiny.position[1], 100 + 2e-9, 1e-12);
  // A billion seconds in 60 s steps is over the step limit: refused before any work.
  const auto huge = advect::advect(field, {100, 100, 100}, 0, 1e9,
                                   {.method = Method::kRk4, .step_s = 60, .max_steps = 1000});
  EXPECT_EQ(huge.stop, Stop::kStepLimit);
  EXPECT_EQ(huge.evaluations, 0u);
  // The adaptive pair gets there in few steps (wind constant in time beyond t1).
  for (const Method m : {Method::kDopri5, Method::kRosenbrock}) {
    const auto far = advect::advect(uniform({0, 0, 0}), {100, 100, 100}, 0, 1e9, {.method = m});
    EXPECT_EQ(far.stop, Stop::kReached) << advect::method_name(m);
  }
}

TEST(AdvectionEdgeCasesTest, BadArgumentsAreRefused) {
  const auto field = uniform({1, 0, 0});
  EXPECT_THROW(advect::advect(field, {std::nan(""), 0, 0}, 0, 1), Error);
  EXPECT_THROW(advect::advect(field, {1, 1, 1}, 0, INFINITY), Error);
  EXPECT_THROW(advect::advect(field, {1, 1, 1}, 0, 1, {.step_s = 0}), Error);
  EXPECT_THROW(advect::advect(field, {1, 1, 1}, 0, 1, {.rtol = -1}), Error);
  EXPECT_THROW(advect::advect(field, {1, 1, 1}, 0, 1, {.atol = {0, 1, 1}}), Error);
}

}  // namespace
}  // namespace strielad::testing

namespace strielad::advect {
namespace {

TEST(IntegratorNamesTest, EveryMethodByItsNameAndOthersRefused) {
  for (const Method m : {Method::kEuler, Method::kRk4, Method::kDopri5, Method::kRosenbrock}) {
    EXPECT_EQ(parse_method(method_name(m)), m);
  }
  EXPECT_THROW(parse_method("rk45"), Error);
  EXPECT_THROW(parse_method(""), Error);
}

}  // namespace
}  // namespace strielad::advect
