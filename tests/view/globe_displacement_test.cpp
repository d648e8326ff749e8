// SPDX-License-Identifier: Apache-2.0
// Displacement maps on the globe (lib/view/displacement_map.h): the lattice spans
// longitude, latitude and height, and moved_on_globe (the geometry vertex shader's maths
// on the CPU) moves an ECEF vertex in those, back onto the globe at its exaggerated
// height. A constant zonal wind u moves a point at latitude phi by u t / (R cos phi)
// degrees east at the same height, across the antimeridian too; the map agrees with
// advecting each point itself on a varied global wind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "lod/lod_test_grids.h"
#include "lod/wgs84_globe.h"
#include "view/displacement_map.h"

namespace strielad::view {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kEarthRadiusM = 6371008.8;  // lib/advect's sphere

// A global store's axes: longitudes -180..180 every 7.5 degrees (periodic: the last is
// the first + 360), latitudes -90..90 every 7.5, heights 0..15 km on 7 levels.
format::Manifest global_manifest() {
  using lod::testing::linspace;
  format::Manifest m;
  m.x = Axis{"lon", AxisKind::kLongitude, "degrees_east", "longitude", "", "", linspace(-180, 180, 49)};
  m.x.periodic = true;
  m.y = Axis{"lat", AxisKind::kLatitude, "degrees_north", "latitude", "", "", linspace(-90, 90, 25)};
  m.z = Axis{"height", AxisKind::kHeight, "m", "", "", "up", linspace(0, 15000, 7)};
  m.time = TimeAxis{"time", "seconds since 2024-06-21 00:00:00", "standard", {0, 300}};
  m.brick = 16;
  return m;
}

WindStep global_wind(const format::Manifest& m, const advect::WindFormula& formula) {
  advect::WindGrid grid;
  grid.axes = {m.x.values, m.y.values, m.z.values};
  grid.periodic_x = true;
  return WindStep{.field = advect::sample_wind(grid, 0, 300, formula),
                  .units = WindUnits{},
                  .step = 0,
                  .seconds = 300};
}

lod::WorldFrame globe_frame(const format::Manifest& m) {
  return lod::WorldFrame(m, {.vertical_exaggeration = 1.0, .shape = lod::FrameShape::kGlobe});
}

// {degrees east (the short way), degrees north, km up} from `from` to `to` (ECEF km).
Vec3 geodetic_move(const Vec3& from, const Vec3& to, double exaggeration) {
  const auto a = lod::ecef_km_to_geodetic(from);
  const auto b = lod::ecef_km_to_geodetic(to);
  return {std::remainder(b.lon_deg - a.lon_deg, 360.0), b.lat_deg - a.lat_deg,
          (b.height_km - a.height_km) / exaggeration};
}

TEST(GlobeDisplacementTest, AConstantZonalWindMovesEastByUtOverRCosLatAtTheSameHeight) {
  const auto m = global_manifest();
  const auto frame = globe_frame(m);
  ASSERT_TRUE(frame.globe());
  constexpr double u = 20.0;
  const WindStep wind = global_wind(m, [](double, double, double, double) {
    return Vec3{u, 0.0, 0.0};
  });
  const DisplacementMap map = compute_displacement_map(wind, frame);
  ASSERT_TRUE(map.globe);
  ASSERT_TRUE(map.periodic);
  EXPECT_DOUBLE_EQ(map.box.hi[0] - map.box.lo[0], 360.0);
  EXPECT_NEAR(map.box.lo[1], -90.0, 1e-9);
  EXPECT_NEAR(map.box.hi[1], 90.0, 1e-9);
  constexpr double kExaggeration = 20.0;
  int checked = 0;
  // 175 and -179 E: the antimeridian lies between them and the map's seam at -180.
  for (const double lon : {-179.0, -100.0, 0.0, 13.0, 130.0, 175.0, 179.9}) {
    for (const double lat : {-75.0, -30.0, 0.0, 20.0, 47.5, 80.0}) {
      for (const double h_km : {0.5, 5.0, 12.0}) {
        const Vec3 p = lod::geodetic_to_ecef_km(lon, lat, h_km * kExaggeration);
        for (const double s : {0.0, 75.0, 300.0}) {
          const Vec3 d = geodetic_move(p, map.moved_on_globe(p, s, kExaggeration), kExaggeration);
          const double expected = u * s / (kEarthRadiusM * std::cos(lat * kDeg)) / kDeg;
          EXPECT_NEAR(d[0], expected, 1e-6 + 1e-4 * expected)
              << "lon " << lon << " lat " << lat << " h " << h_km << " s " << s;
          EXPECT_NEAR(d[1], 0.0, 1e-7);
          EXPECT_NEAR(d[2] * 1000.0, 0.0, 1e-3);  // metres, true scale
          ++checked;
        }
      }
    }
  }
  EXPECT_EQ(checked, 7 * 6 * 3 * 3);
  // Across the antimeridian: 179.9 E with a wind that takes it more than 0.1 degree east.
  const Vec3 p = lod::geodetic_to_ecef_km(179.9, 60.0, 1.0);
  const auto moved = lod::ecef_km_to_geodetic(map.moved_on_globe(p, 300.0, 1.0));
  EXPECT_LT(moved.lon_deg, -179.0);  // on the other side
  EXPECT_NEAR(moved.lon_deg + 360.0 - 179.9,
              u * 300.0 / (kEarthRadiusM * std::cos(60.0 * kDeg)) / kDeg, 1e-6);
  EXPECT_EQ(map.stopped, 0u);
}

TEST(GlobeDisplacementTest, NotMovedAtTimeZero) {
  const auto m = global_manifest();
  const auto frame = globe_frame(m);
  const WindStep wind = global_wind(m, [](double, double lat, double, double) {
    return Vec3{30.0 * std::cos(lat * kDeg), 5.0, 0.01};
  });
  const DisplacementMap map = compute_displacement_map(wind, frame);
  for (const double lat : {-89.99, -45.0, 0.0, 60.0, 90.0}) {
    const Vec3 p = lod::geodetic_to_ecef_km(33.0, lat, 100.0);
    const Vec3 q = map.moved_on_globe(p, 0.0, 20.0);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(q[a], p[a], 1e-9) << "lat " << lat;
  }
}

// Max distance (m, true scale) between where the map moves a point and where advecting
// it itself takes it, over points spread through the globe up to 80 degrees of latitude.
double max_error_m(const DisplacementMap& map, const WindStep& wind, const lod::WorldFrame& frame,
                   double s, double* max_displacement_m) {
  double worst = 0;
  *max_displacement_m = 0;
  for (int i = 0; i < 7 * 9 * 5; ++i) {
    const double lon = -180.0 + 360.0 * ((i % 7) + 0.37) / 7;
    const double lat = -80.0 + 160.0 * ((i / 7 % 9) + 0.5) / 9;
    const double h_km = 0.5 + 12.0 * ((i / 63) + 0.5) / 5;
    const Vec3 p = lod::geodetic_to_ecef_km(lon, lat, h_km);
    const Vec3 start = wind.units.to_wind(frame.to_axis(frame.place_geographic(lon, lat, h_km)));
    const auto r = advect::advect(wind.field, start, 0, s);
    if (r.stop != advect::Stop::kReached) continue;
    const Vec3 exact = frame.to_world(wind.units.to_axis(r.position));
    const Vec3 moved = map.moved_on_globe(p, s, 1.0);
    worst = std::max(worst, length(sub(exact, moved)) * 1000);
    *max_displacement_m = std::max(*max_displacement_m, length(sub(exact, p)) * 1000);
  }
  return worst;
}

TEST(GlobeDisplacementTest, TheMapAgreesWithAdvectingEachPoint) {
  const auto m = global_manifest();
  const auto frame = globe_frame(m);
  // Jets, waves along the parallels and a vertical shear, zero at the poles' rows; the
  // vertical wind vanishes at the ground (no trajectory leaves through the bottom).
  const WindStep wind = global_wind(m, [](double lon, double lat, double z, double t) {
    const double c = std::cos(lat * kDeg);
    return Vec3{c * (15.0 + 25.0 * std::sin(2 * lat * kDeg) * std::sin(2 * lat * kDeg) +
                     8.0 * std::sin(3 * lon * kDeg) + z / 1000.0),
                c * 10.0 * std::cos(2 * lon * kDeg + t / 3000.0),
                0.05 * std::sin(lon * kDeg) * c * z / 15000.0};
  });
  const DisplacementMap coarse = compute_displacement_map(wind, frame, {.lattice = {25, 13, 8}});
  const DisplacementMap fine = compute_displacement_map(wind, frame);
  double moved = 0;
  const double coarse_end = max_error_m(coarse, wind, frame, 300, &moved);
  const double fine_end = max_error_m(fine, wind, frame, 300, &moved);
  const double fine_mid = max_error_m(fine, wind, frame, 130, &moved);
  std::printf("globe displacement map vs per-point RK4 after 300 s: max error %.1f m (lattice "
              "25x13x8), %.1f m (%zux%zux%zu); after 130 s %.1f m; largest displacement %.0f m\n",
              coarse_end, fine_end, fine.lattice[0], fine.lattice[1], fine.lattice[2], fine_mid,
              moved);
  EXPECT_GT(moved, 3000.0);  // up to 20 m/s for 300 s
  EXPECT_LT(fine_end, coarse_end);
  EXPECT_LT(fine_end, 0.02 * moved);
  EXPECT_LT(fine_mid, 0.02 * moved);
}

}  // namespace
}  // namespace strielad::view
