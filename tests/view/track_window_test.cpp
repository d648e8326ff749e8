// SPDX-License-Identifier: Apache-2.0
// The part of each flight track drawn at a moment (lib/view/track_window.h): cut at
// both ends of the window by interpolation, the aircraft's position at `now`, and the
// time boundaries (before the first report, at a report, after the last, window 0).
#include <gtest/gtest.h>

#include "lod/lod_test_grids.h"
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

}  // namespace
}  // namespace strielad::view
