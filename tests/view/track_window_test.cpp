// SPDX-License-Identifier: Apache-2.0
// The part of each flight track drawn at a moment (lib/view/track_window.h): cut at
// both ends of the window by interpolation, the aircraft's position at `now`, and the
// time boundaries (before the first report, at a report, after the last, window 0); on
// the globe, positions where PROJ's cs2cs puts them (ECEF at the exaggeration) and long
// legs cut along the great circle so that they stay above the surface.
#include <gtest/gtest.h>

#include <cmath>

#include "lod/lod_test_grids.h"
#include "lod/wgs84_globe.h"
#include "support/cs2cs.h"
#include "view/track_window.h"

namespace strielad::view {
namespace {

// One track: reports at 0, 60, 120, 180 s, longitude 8, 9, 10, 11 E at 50 N, climbing.
geo::FlightTracks one_track() {
  geo::FlightTracks tracks;
  geo::FlightTrack t;
  t.id = "T";
  t.seconds = {0, 60, 120, 180};
  t.lon = {8, 9, 10, 11};
  t.lat = {50, 50, 50, 50};
  t.altitude_m = {1000, 2000, 3000, 4000};
  tracks.tracks.push_back(t);
  tracks.reports = 4;
  return tracks;
}

class TrackWindowTest : public ::testing::Test {
 protected:
  lod::WorldFrame frame{lod::testing::geographic_manifest(11, 8, {0.0, 12000.0}),
                        lod::WorldFrameOptions{.vertical_exaggeration = 1.0}};
  double x(double lon) const { return frame.geographic_to_world(lon, frame.lat0())[0]; }
};

TEST_F(TrackWindowTest, TheLastTwoMinutesCutByInterpolation) {
  const TrackLines lines = window_tracks(one_track(), 150, 120, frame);
  EXPECT_EQ(lines.tracks_shown, 1u);
  // 30 s .. 60 .. 120 .. 150 s: three segments.
  ASSERT_EQ(lines.segment_count(), 3u);
  EXPECT_NEAR(lines.segments[0], x(8.5), 1e-3);  // at 30 s
  EXPECT_NEAR(lines.segments[2], 1.5, 1e-6);     // km
  EXPECT_NEAR(lines.segments[3], x(9), 1e-3);
  EXPECT_NEAR(lines.segments[15], x(10.5), 1e-3);  // the segment's end at 150 s
  ASSERT_EQ(lines.head_count(), 1u);
  EXPECT_NEAR(lines.heads[0], x(10.5), 1e-3);
  EXPECT_NEAR(lines.heads[2], 3.5, 1e-6);
  // Connected: each segment starts where the previous ended.
  for (std::size_t s = 1; s < lines.segment_count(); ++s) {
    for (int a = 0; a < 3; ++a) EXPECT_EQ(lines.segments[s * 6 + a], lines.segments[s * 6 - 3 + a]);
  }
}

TEST_F(TrackWindowTest, TimeBoundaries) {
  const auto tracks = one_track();
  EXPECT_EQ(window_tracks(tracks, -1, 120, frame).tracks_shown, 0u);  // not yet flying
  const auto first = window_tracks(tracks, 0, 120, frame);           // at the first report
  EXPECT_EQ(first.segment_count(), 0u);
  EXPECT_EQ(first.head_count(), 1u);
  const auto at_report = window_tracks(tracks, 120, 60, frame);  // exactly one segment
  ASSERT_EQ(at_report.segment_count(), 1u);
  EXPECT_NEAR(at_report.segments[0], x(9), 1e-3);
  EXPECT_NEAR(at_report.segments[3], x(10), 1e-3);
  const auto landed = window_tracks(tracks, 240, 120, frame);  // the last 60 s still shown
  EXPECT_EQ(landed.segment_count(), 1u);
  EXPECT_EQ(landed.head_count(), 0u);
  EXPECT_NEAR(landed.segments[3], x(11), 1e-3);
  EXPECT_EQ(window_tracks(tracks, 301, 120, frame).tracks_shown, 0u);  // gone
  const auto heads_only = window_tracks(tracks, 90, 0, frame);
  EXPECT_EQ(heads_only.segment_count(), 0u);
  ASSERT_EQ(heads_only.head_count(), 1u);
  EXPECT_NEAR(heads_only.heads[0], x(9.5), 1e-3);
}

TEST_F(TrackWindowTest, ManyTracks) {
  geo::FlightTracks many;
  for (int i = 0; i < 27000; ++i) {
    auto t = one_track().tracks[0];
    for (auto& s : t.seconds) s += i % 300;
    many.tracks.push_back(t);
  }
  const auto lines = window_tracks(many, 200, 120, frame);
  EXPECT_EQ(lines.tracks_shown, 90u * 201u);  // those whose first report is at most 200 s
  EXPECT_GT(lines.segment_count(), 27000u);
}

// A global 7.5-degree grid, heights 0..15 km, on the globe at 20 times.
constexpr double kGlobeExaggeration = 20.0;
lod::WorldFrame globe_frame() {
  format::Manifest m = lod::testing::geographic_manifest(48, 25, {0.0, 7500.0, 15000.0});
  m.x.values = lod::testing::linspace(0.0, 352.5, 48);
  m.y.values = lod::testing::linspace(90.0, -90.0, 25);
  m.brick = 8;
  return lod::WorldFrame(m, lod::WorldFrameOptions{.vertical_exaggeration = kGlobeExaggeration,
                                                   .shape = lod::FrameShape::kAuto});
}

Vec3 point_of(const std::vector<float>& v, std::size_t k) {
  return {v[3 * k], v[3 * k + 1], v[3 * k + 2]};
}

double distance(const Vec3& a, const Vec3& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

TEST(TrackWindowGlobeTest, ReportsLandWhereProjPlacesThemAtTheExaggeration) {
  if (!strielad::testing::have_cs2cs()) GTEST_SKIP() << "cs2cs (proj-bin) not installed";
  const lod::WorldFrame frame = globe_frame();
  ASSERT_TRUE(frame.globe());
  // Short hops (under half a degree: one segment each) over places far apart on the
  // Earth: across the antimeridian, near a pole, south of the equator.
  geo::FlightTracks tracks;
  const std::vector<std::array<double, 3>> reports = {
      {179.8, 20.0, 11000.0}, {-179.9, 20.1, 11500.0},  // 180 E
      {10.0, 88.0, 9000.0},   {10.3, 88.2, 9500.0},     // the Arctic
      {-47.9, -15.8, 300.0},  {-47.7, -15.6, 2500.0}};  // Brasilia climbing
  for (std::size_t k = 0; k < reports.size(); k += 2) {
    geo::FlightTrack t;
    t.id = std::to_string(k);
    t.seconds = {0, 60};
    for (std::size_t r = k; r < k + 2; ++r) {
      t.lon.push_back(reports[r][0]);
      t.lat.push_back(reports[r][1]);
      t.altitude_m.push_back(reports[r][2]);
    }
    tracks.tracks.push_back(t);
  }
  // At 60 s the window of 60 s is each whole leg; the heads are the last reports.
  const TrackLines lines = window_tracks(tracks, 60, 60, frame);
  ASSERT_EQ(lines.segment_count(), 3u);
  ASSERT_EQ(lines.head_count(), 3u);
  std::vector<std::array<double, 3>> exaggerated;
  for (const auto& r : reports) exaggerated.push_back({r[0], r[1], r[2] * kGlobeExaggeration});
  const auto proj = strielad::testing::cs2cs_3d("+proj=longlat +datum=WGS84",
                                                "+proj=geocent +datum=WGS84 +units=m", exaggerated);
  ASSERT_TRUE(proj);
  for (std::size_t k = 0; k < reports.size(); ++k) {
    const Vec3 theirs{(*proj)[k][0] * 1e-3, (*proj)[k][1] * 1e-3, (*proj)[k][2] * 1e-3};
    // Floats of ECEF km: within a metre.
    EXPECT_LT(distance(point_of(lines.segments, k), theirs), 1e-3)
        << reports[k][0] << " E " << reports[k][1] << " N";
    if (k % 2 == 1) {
      EXPECT_LT(distance(point_of(lines.heads, k / 2), theirs), 1e-3);
    }
  }
}

TEST(TrackWindowGlobeTest, LongLegsFollowTheGreatCircleAboveTheSurface) {
  const lod::WorldFrame frame = globe_frame();
  // Frankfurt to New York in one leg, 10 km up: about 56 degrees of arc.
  geo::FlightTracks tracks;
  geo::FlightTrack t;
  t.id = "LH400";
  t.seconds = {0, 28800};
  t.lon = {8.57, -73.78};
  t.lat = {50.03, 40.64};
  t.altitude_m = {10000, 10000};
  tracks.tracks.push_back(t);
  const TrackLines lines = window_tracks(tracks, 28800, 28800, frame);
  ASSERT_GE(lines.segment_count(), 100u);  // pieces of at most half a degree
  const Vec3 a = lod::geodetic_to_ecef_km(8.57, 50.03, 0), b = lod::geodetic_to_ecef_km(-73.78, 40.64, 0);
  const Vec3 pole{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double pole_norm = std::hypot(pole[0], pole[1], pole[2]);
  double highest_lat = -90;
  for (std::size_t k = 0; k < 2 * lines.segment_count(); ++k) {
    const Vec3 p = point_of(lines.segments, k);
    const auto g = lod::ecef_km_to_geodetic(p);
    // Every point 10 km up (200 km drawn), on the great circle's plane (within the
    // ellipsoid's few km of difference from the sphere).
    EXPECT_NEAR(g.height_km, 10.0 * kGlobeExaggeration, 0.01);
    EXPECT_LT(std::fabs(p[0] * pole[0] + p[1] * pole[1] + p[2] * pole[2]) / pole_norm, 25.0);
    highest_lat = std::max(highest_lat, g.lat_deg);
    // Each piece's middle stays within 0.1 km under its ends' height.
    if (k % 2 == 1) {
      const Vec3 q = point_of(lines.segments, k - 1);
      const Vec3 mid{(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2};
      EXPECT_GT(lod::ecef_km_to_geodetic(mid).height_km, 10.0 * kGlobeExaggeration - 0.1);
    }
  }
  // The great circle bows north of both ends to 54.2 N (the rhumb line would not).
  EXPECT_NEAR(highest_lat, 54.19, 0.05);
  // The head halfway in time is halfway along the arc, not at the mean longitude.
  const TrackLines half = window_tracks(tracks, 14400, 0, frame);
  ASSERT_EQ(half.head_count(), 1u);
  const auto h = lod::ecef_km_to_geodetic(point_of(half.heads, 0));
  EXPECT_NEAR(h.lat_deg, 53.28, 0.01);
}

}  // namespace
}  // namespace strielad::view
