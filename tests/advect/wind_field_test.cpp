// SPDX-License-Identifier: Apache-2.0
// WindField: trilinear in space on real (non-uniform, descending) axes, linear in time,
// the unit conversions of geographic and pressure axes, and what it refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "advect/integrators.h"
#include "core/error.h"
#include "wind_fields.h"

namespace strielad::testing {
namespace {

using advect::Sample;

advect::WindGrid metric_grid() {
  advect::WindGrid g;
  g.horizontal = advect::Horizontal::kMetres;
  g.axes = {std::vector<double>{0, 100, 300, 700}, std::vector<double>{500, 200, 0},  // y descending
            std::vector<double>{0, 50, 1000}};
  return g;
}

TEST(WindFieldTest, ALinearFieldIsReproducedExactlyOnNonUniformDescendingAxes) {
  const auto field = sample_wind(metric_grid(), 0, 600, [](double x, double y, double z, double t) {
    return Vec3{1 + 0.01 * x - 0.02 * y + 0.001 * t, 0.5 * y, -z * 0.003};
  });
  Vec3 rate{};
  ASSERT_EQ(field.rate({250, 333, 700}, 150, rate), Sample::kOk);
  EXPECT_NEAR(rate[0], 1 + 2.5 - 6.66 + 0.15, 1e-5);
  EXPECT_NEAR(rate[1], 166.5, 1e-4);
  EXPECT_NEAR(rate[2], -2.1, 1e-5);
}

TEST(WindFieldTest, GeographicRatesDivideByTheEarthRadiusAndCosLatitude) {
  advect::WindGrid g;
  g.axes = {linspace(0, 10, 6), linspace(40, 50, 6), linspace(0, 10000, 3)};
  const auto field = sample_wind(g, 0, 1, [](double, double, double, double) { return Vec3{10, 5, 2}; });
  Vec3 rate{};
  ASSERT_EQ(field.rate({5, 45, 500}, 0, rate), Sample::kOk);
  const double deg = 180 / std::numbers::pi;
  EXPECT_NEAR(rate[0], 10 / (advect::kEarthRadiusM * std::cos(45 / deg)) * deg, 1e-15);
  EXPECT_NEAR(rate[1], 5 / advect::kEarthRadiusM * deg, 1e-15);
  EXPECT_DOUBLE_EQ(rate[2], 2);
}

TEST(WindFieldTest, PressureAxesTakeOmegaInPascalsPerSecond) {
  advect::WindGrid g;
  g.vertical = advect::Vertical::kPascals;
  g.axes = {linspace(0, 10, 3), linspace(0, 10, 3), std::vector<double>{100000, 85000, 50000}};
  const auto field = sample_wind(g, 0, 1, [](double, double, double p, double) {
    return Vec3{0, 0, -0.001 * p};  // rising air: pressure falls
  });
  Vec3 rate{};
  ASSERT_EQ(field.rate({5, 5, 90000}, 0, rate), Sample::kOk);
  EXPECT_NEAR(rate[2], -90.0, 1e-3);
}

TEST(WindFieldTest, OutsideAndFillAreToldApart) {
  auto g = metric_grid();
  advect::WindSlice s0, s1;
  for (std::size_t i = 0; i < g.count(); ++i) {
    s0.u.push_back(1), s0.v.push_back(0), s0.w.push_back(0);
    s1 = s0;
  }
  s1.v[5] = std::nanf("");  // one fill sample at t1 only
  const advect::WindField field(g, 0, s0, 1, s1);
  Vec3 rate{7, 7, 7};
  EXPECT_EQ(field.rate({-1, 100, 10}, 0, rate), Sample::kOutside);
  EXPECT_EQ(field.rate({10, 600, 10}, 0, rate), Sample::kOutside);
  // Sample 5 is x = 1, y = 1 (y = 200), z = 0: the cells around it have no wind.
  EXPECT_EQ(field.rate({150, 300, 10}, 0.5, rate), Sample::kMissing);
  EXPECT_EQ(rate, (Vec3{7, 7, 7}));
  EXPECT_EQ(field.rate({500, 100, 500}, 0.5, rate), Sample::kOk);
}

TEST(WindFieldTest, NearAPoleTheLongitudeRateIsLargeButFinite) {
  advect::WindGrid g;
  g.axes = {linspace(0, 360, 9), linspace(80, 90, 3), linspace(0, 1000, 2)};
  const auto field = sample_wind(g, 0, 1, [](double, double, double, double) { return Vec3{10, 0, 0}; });
  Vec3 rate{};
  ASSERT_EQ(field.rate({10, 90, 0}, 0, rate), Sample::kOk);
  EXPECT_TRUE(std::isfinite(rate[0]));
  EXPECT_GT(rate[0], 1.0);
}

TEST(WindFieldTest, BadGridsAndComponentsAreRefusedByName) {
  auto g = metric_grid();
  const auto make = [&](advect::WindGrid grid, double t0, double t1) {
    return sample_wind(std::move(grid), t0, t1, [](double, double, double, double) { return Vec3{}; });
  };
  try {
    auto bad = g;
    bad.axes[2] = {0, 50, 50};
    make(bad, 0, 1);
    FAIL() << "accepted a repeated z value";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::kInvalidArgument);
    EXPECT_NE(std::string(e.what()).find("axis z"), std::string::npos) << e.what();
  }
  EXPECT_THROW(make(g, 1, 1), Error);
  EXPECT_THROW(make(g, 0, std::nan("")), Error);
  auto one = g;
  one.axes[0] = {5};
  EXPECT_THROW(make(one, 0, 1), Error);
  advect::WindGrid geo;
  geo.axes = {linspace(0, 1, 2), std::vector<double>{80, 95}, linspace(0, 1, 2)};
  EXPECT_THROW(make(geo, 0, 1), Error);
  advect::WindSlice short_slice{{1.0f}, {1.0f}, {1.0f}};
  EXPECT_THROW(advect::WindField(g, 0, short_slice, 1, short_slice), Error);
}

TEST(WindFieldTest, TrajectoriesCrossAPeriodicGridsSeam) {
  // A global grid 0 .. 360 (the first meridian repeated), 20 m/s eastward at the equator:
  // a point at 359 E goes on past the seam instead of stopping at the grid's edge.
  advect::WindGrid g;
  g.axes = {linspace(0, 360, 145), linspace(-10, 10, 9), linspace(0, 1000, 3)};
  g.periodic_x = true;
  const auto field = sample_wind(g, 0, 3600, [](double, double, double, double) { return Vec3{20, 0, 0}; });
  EXPECT_TRUE(field.inside({365, 0, 500}));
  EXPECT_TRUE(field.inside({-5, 0, 500}));
  const advect::AdvectResult r = advect::advect(field, {359.5, 0, 500}, 0, 3600);
  EXPECT_EQ(r.stop, advect::Stop::kReached);
  // 72 km east at the equator: 72000 / (6371008.8 pi / 180) = 0.6475 degrees.
  EXPECT_NEAR(r.position[0], 359.5 + 72000.0 / (advect::kEarthRadiusM * std::numbers::pi / 180), 1e-6);
  // Without the flag the same grid stops the point at its edge.
  g.periodic_x = false;
  const auto bounded = sample_wind(g, 0, 3600, [](double, double, double, double) { return Vec3{20, 0, 0}; });
  EXPECT_NE(advect::advect(bounded, {359.5, 0, 500}, 0, 3600).stop, advect::Stop::kReached);
  g.horizontal = advect::Horizontal::kMetres;
  g.periodic_x = true;
  EXPECT_THROW(sample_wind(g, 0, 1, [](double, double, double, double) { return Vec3{}; }), Error);
}

}  // namespace
}  // namespace strielad::testing
