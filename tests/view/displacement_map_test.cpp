// SPDX-License-Identifier: Apache-2.0
// Displacement maps (lib/view/displacement_map.h): a uniform wind moves every point by
// wind x time (in the world frame's equirectangular km), keyframes interpolate in time,
// the map agrees with advecting each point itself on the sample generator's wind to a
// stated bound that shrinks with a finer lattice, and trajectories that stop leave
// finite displacements.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "lod/lod_test_grids.h"
#include "support/expect_error.h"
#include "support/temp_dir.h"
#include "support/wind_store.h"
#include "view/displacement_map.h"

namespace strielad::view {
namespace {

using strielad::testing::expect_error;

constexpr double kDeg = std::numbers::pi / 180.0;

// Wind `formula` on the axes of `m` (degrees, metres), steps 300 s apart.
WindStep formula_wind(const format::Manifest& m, const advect::WindFormula& formula) {
  advect::WindGrid grid;
  grid.axes = {m.x.values, m.y.values, m.z.values};
  return WindStep{.field = advect::sample_wind(grid, 0, 300, formula),
                  .units = WindUnits{},
                  .step = 3,
                  .seconds = 300};
}

TEST(DisplacementMapTest, AUniformWindMovesEveryPointByWindTimesTime) {
  const auto m = lod::testing::geographic_manifest(11, 8, {12000.0, 3000.0, 0.0});
  const lod::WorldFrame frame(m, {.vertical_exaggeration = 1.0});
  const WindStep wind = formula_wind(m, [](double, double, double, double) {
    return Vec3{10.0, 0.0, 0.0};
  });
  DisplacementOptions options;
  options.lattice = {9, 7, 5};
  const DisplacementMap map = compute_displacement_map(wind, frame, options);
  EXPECT_EQ(map.step, 3u);
  EXPECT_EQ(map.keyframes, 5u);
  ASSERT_EQ(map.displacement.size(), map.points() * 3 * map.keyframes);
  const double lat0 = frame.lat0();
  std::size_t checked = 0;
  for (double fx : {0.1, 0.4, 0.8}) {
    for (double fy : {0.05, 0.5, 0.95}) {
      for (double fz : {0.0, 0.3, 1.0}) {
        Vec3 p{};
        const Vec3 f{fx, fy, fz};
        for (int a = 0; a < 3; ++a) p[a] = map.box.lo[a] + f[a] * (map.box.hi[a] - map.box.lo[a]);
        const double lat = frame.to_axis(p)[1];
        // 10 m/s for 300 s = 3 km along the parallel, drawn at cos(lat0)/cos(lat).
        const double expected = 3.0 * std::cos(lat0 * kDeg) / std::cos(lat * kDeg);
        for (const double s : {300.0, 150.0, 40.0}) {
          const Vec3 d = map.displacement_at(p, s);
          // Lattice interpolation of cos(lat0)/cos(lat) across 1 degree cells: < 1e-3.
          EXPECT_NEAR(d[0], expected * s / 300.0, 2e-3 * expected) << "at " << fx << "," << fy << "," << fz;
          EXPECT_NEAR(d[1], 0.0, 1e-9);
          EXPECT_NEAR(d[2], 0.0, 1e-9);
          ++checked;
        }
        EXPECT_EQ(map.displacement_at(p, 0.0)[0], 0.0);
        EXPECT_NEAR(map.displacement_at(p, 1e9)[0], expected, 2e-3 * expected);  // clamped
      }
    }
  }
  EXPECT_EQ(checked, 81u);
  // The east face flows out: those trajectories stop at the boundary, inside the box.
  EXPECT_EQ(map.stopped, map.lattice[1] * map.lattice[2]);
  const Vec3 east{map.box.hi[0], 0.0, 5.0};
  const auto d = map.displacement_at(east, 300);
  EXPECT_GE(d[0], 0.0);
  EXPECT_LT(d[0], 1e-3);
}

TEST(DisplacementMapTest, StoppedTrajectoriesLeaveFiniteDisplacements) {
  const auto m = lod::testing::geographic_manifest(11, 8, {12000.0, 3000.0, 0.0});
  const lod::WorldFrame frame(m, {.vertical_exaggeration = 1.0});
  // Fill west of 9 E, a strong updraft and a jet elsewhere.
  const WindStep wind = formula_wind(m, [](double lon, double, double, double) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return lon < 9 ? Vec3{nan, nan, nan} : Vec3{80.0, -40.0, 30.0};
  });
  const DisplacementMap map = compute_displacement_map(wind, frame, {.lattice = {12, 9, 6}});
  EXPECT_GT(map.stopped, 0u);
  for (const float v : map.displacement) ASSERT_TRUE(std::isfinite(v));
}

class DisplacementAccuracyTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir();
    store_ = new std::shared_ptr<const Store>(Store::open(testing::write_wind_store(dir_->path())));
  }
  static void TearDownTestSuite() {
    delete store_;
    delete dir_;
  }
  static inline testing::TempDir* dir_ = nullptr;
  static inline std::shared_ptr<const Store>* store_ = nullptr;
};

// Max distance (m) between the map's displacement and the point advected itself, over
// points spread through the inner 80% of the domain, after `s` seconds.
double max_error_m(const DisplacementMap& map, const WindStep& wind, const lod::WorldFrame& frame,
                   double s, double* max_displacement_m) {
  double worst = 0;
  *max_displacement_m = 0;
  for (int i = 0; i < 343; ++i) {
    const Vec3 f{0.1 + 0.8 * ((i % 7) + 0.5) / 7, 0.1 + 0.8 * ((i / 7 % 7) + 0.5) / 7,
                      0.05 + 0.6 * ((i / 49) + 0.5) / 7};
    Vec3 p{};
    for (int a = 0; a < 3; ++a) p[a] = map.box.lo[a] + f[a] * (map.box.hi[a] - map.box.lo[a]);
    const auto r = advect::advect(wind.field, wind.units.to_wind(frame.to_axis(p)), 0, s);
    if (r.stop != advect::Stop::kReached) continue;
    const Vec3 exact = frame.to_world(wind.units.to_axis(r.position));
    const Vec3 moved = add(p, map.displacement_at(p, s));
    worst = std::max(worst, length(sub(exact, moved)) * 1000);
    *max_displacement_m = std::max(*max_displacement_m, length(sub(exact, p)) * 1000);
  }
  return worst;
}

TEST_F(DisplacementAccuracyTest, TheMapAgreesWithAdvectingEachPoint) {
  const WindStep wind = load_wind_step(**store_, 0, WindNames{}, 0);
  const lod::WorldFrame frame((*store_)->manifest(), {.vertical_exaggeration = 1.0});
  const DisplacementMap coarse = compute_displacement_map(wind, frame, {.lattice = {12, 10, 12}});
  const DisplacementMap fine = compute_displacement_map(wind, frame, {.lattice = {48, 40, 48}});
  double moved = 0;
  const double coarse_end = max_error_m(coarse, wind, frame, 300, &moved);
  const double fine_end = max_error_m(fine, wind, frame, 300, &moved);
  const double fine_mid = max_error_m(fine, wind, frame, 130, &moved);
  std::printf("displacement map vs per-point RK4 after 300 s: max error %.1f m (lattice "
              "12x10x12), %.1f m (48x40x48); after 130 s %.1f m; largest displacement %.0f m\n",
              coarse_end, fine_end, fine_mid, moved);
  EXPECT_GT(moved, 1000.0);  // the sample wind moves air by kilometres in 5 minutes
  EXPECT_LT(fine_end, coarse_end);
  EXPECT_LT(fine_end, 0.02 * moved);
  EXPECT_LT(fine_mid, 0.02 * moved);
}

TEST(DisplacementMapTest, BadOptionsAreRefused) {
  const auto m = lod::testing::geographic_manifest(4, 4, {0.0, 1000.0});
  const lod::WorldFrame frame(m, {.vertical_exaggeration = 1.0});
  const WindStep wind = formula_wind(m, [](double, double, double, double) {
    return Vec3{1.0, 0.0, 0.0};
  });
  expect_error([&] { compute_displacement_map(wind, frame, {.lattice = {1, 4, 4}}); },
               ErrorCode::kInvalidArgument, {"lattice", "axis 0"});
  expect_error([&] { compute_displacement_map(wind, frame, {.keyframes = 1}); },
               ErrorCode::kInvalidArgument, {"keyframes"});
  DisplacementOptions bad_step;
  bad_step.integrator.step_s = -1;
  EXPECT_THROW(compute_displacement_map(wind, frame, bad_step), Error);
}

}  // namespace
}  // namespace strielad::view
