// SPDX-License-Identifier: Apache-2.0
// Synthetic flight tracks (lib/synthetic/sample_tracks.h): readable by the track loader,
// over the sample domain, one report a minute, deterministic from the seed, and bad
// arguments refused.
#include <gtest/gtest.h>

#include "core/file_io.h"
#include "scenery/flight_tracks.h"
#include "synthetic/sample_grid.h"
#include "synthetic/sample_tracks.h"
#include "support/expect_error.h"
#include "support/temp_dir.h"

namespace strielad::synthetic {
namespace {

using strielad::testing::expect_error;

TEST(SampleTracksTest, TracksOverTheDomainReadableAndDeterministic) {
  testing::TempDir dir;
  const auto result = write_sample_tracks({.tracks = 200, .span_seconds = 900, .seed = 3}, dir / "a.csv");
  EXPECT_EQ(result.tracks, 200u);
  const geo::FlightTracks tracks = geo::load_flight_tracks_csv(dir / "a.csv");
  ASSERT_EQ(tracks.tracks.size(), 200u);
  EXPECT_EQ(tracks.reports, result.reports);
  std::size_t through_centre = 0;
  for (const auto& t : tracks.tracks) {
    ASSERT_GE(t.size(), 20u);  // 20 to 50 minutes of reports
    EXPECT_NEAR(t.seconds[1] - t.seconds[0], 60.0, 1e-3);
    for (std::size_t i = 0; i < t.size(); ++i) {
      EXPECT_GE(t.altitude_m[i], 0.0);
      EXPECT_LE(t.altitude_m[i], 12500.0);
    }
    const std::size_t mid = t.size() / 2;
    // Half-way is within half a report interval (about 8 km) of a point of the domain.
    if (t.lon[mid] > kLonMin - 0.15 && t.lon[mid] < kLonMax + 0.15 && t.lat[mid] > kLatMin - 0.1 &&
        t.lat[mid] < kLatMax + 0.1) {
      ++through_centre;
    }
  }
  EXPECT_EQ(through_centre, 200u);  // every track crosses the domain half-way
  // Every aircraft is in the air from 12:00 UTC (Julian day 2456409.0) for the span (its
  // last report is within one report interval of the span's end or later).
  for (const auto& t : tracks.tracks) {
    const double first = (tracks.reference_julian_day - 2456409.0) * 86400 + t.seconds.front();
    const double last = (tracks.reference_julian_day - 2456409.0) * 86400 + t.seconds.back();
    EXPECT_LE(first, 1e-3) << t.id;
    EXPECT_GE(last, 900.0 - 60.0 - 1e-3) << t.id;
  }
  write_sample_tracks({.tracks = 200, .span_seconds = 900, .seed = 3}, dir / "b.csv");
  EXPECT_EQ(read_file_bytes(dir / "a.csv"), read_file_bytes(dir / "b.csv"));
  write_sample_tracks({.tracks = 200, .span_seconds = 900, .seed = 4}, dir / "c.csv");
  EXPECT_NE(read_file_bytes(dir / "a.csv"), read_file_bytes(dir / "c.csv"));
}

TEST(SampleTracksTest, BadArgumentsAreRefused) {
  testing::TempDir dir;
  expect_error([&] { write_sample_tracks({.tracks = 0}, dir / "x.csv"); },
               ErrorCode::kInvalidArgument, {"--tracks 0"});
  expect_error([&] { write_sample_tracks({.tracks = 1, .span_seconds = -1}, dir / "x.csv"); },
               ErrorCode::kInvalidArgument, {"span"});
}

}  // namespace
}  // namespace strielad::synthetic
