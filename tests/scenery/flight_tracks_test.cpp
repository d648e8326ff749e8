// SPDX-License-Identifier: Apache-2.0
// Flight tracks from CSV (lib/scenery/flight_tracks.h): columns found by name in any order,
// rows of a track gathered and sorted by time, times relative to the earliest report;
// bad files refused with file, line and column.
#include <gtest/gtest.h>

#include <fstream>

#include "scenery/flight_tracks.h"
#include "support/expect_error.h"
#include "support/temp_dir.h"

namespace strielad::geo {
namespace {

using strielad::testing::expect_error;

std::filesystem::path write(const testing::TempDir& dir, const std::string& name,
                            const std::string& text) {
  const auto path = dir / name;
  std::ofstream(path) << text;
  return path;
}

TEST(FlightTracksTest, ColumnsByNameRowsGatheredAndSorted) {
  testing::TempDir dir;
  const auto path = write(dir, "tracks.csv",
                          "callsign,altitude,lat,lon,time,id\r\n"
                          "x,10000,50.5,8.0,2013-04-26T12:01:00Z,DLH1\r\n"
                          "x,11000,51.0,9.0,2013-04-26T12:00:00Z,BAW2\r\n"
                          "x,10500,50.0,7.0,2013-04-26T12:00:00Z,DLH1\n"
                          "\n"
                          "x,11000,51.2,9.5,2013-04-26T13:00:30+01:00,BAW2\n");
  const FlightTracks tracks = load_flight_tracks_csv(path);
  EXPECT_EQ(tracks.reports, 4u);
  EXPECT_DOUBLE_EQ(tracks.reference_julian_day, 2456409.0);  // 2013-04-26 12:00 UTC
  ASSERT_EQ(tracks.tracks.size(), 2u);
  const FlightTrack& dlh = tracks.tracks[0];
  EXPECT_EQ(dlh.id, "DLH1");
  ASSERT_EQ(dlh.size(), 2u);
  EXPECT_NEAR(dlh.seconds[0], 0.0, 1e-4);
  EXPECT_NEAR(dlh.seconds[1], 60.0, 1e-4);
  EXPECT_EQ(dlh.lon[0], 7.0);  // sorted by time
  EXPECT_EQ(dlh.altitude_m[1], 10000.0);
  const FlightTrack& baw = tracks.tracks[1];
  EXPECT_NEAR(baw.seconds[1], 30.0, 1e-4);  // 13:00:30 at +01:00 is 12:00:30 UTC
}

TEST(FlightTracksTest, BadFilesAreRefusedWithLineAndColumn) {
  testing::TempDir dir;
  const std::string header = "id,time,lon,lat,altitude\n";
  expect_error([&] { load_flight_tracks_csv(dir / "missing.csv"); }, ErrorCode::kNotFound,
               {"missing.csv"});
  expect_error([&] { load_flight_tracks_csv(write(dir, "a.csv", "id,time,lon,lat\n")); },
               ErrorCode::kInvalidInput, {"a.csv:1", "altitude"});
  expect_error([&] { load_flight_tracks_csv(write(dir, "b.csv", header + "A,2013-04-26T12:00:00Z,7,50,1e4\nA,2013-04-26T12:01:00Z,seven,50,1e4\n")); },
               ErrorCode::kInvalidInput, {"b.csv:3", "column 3", "seven"});
  expect_error([&] { load_flight_tracks_csv(write(dir, "c.csv", header + "A,noon,7,50,1e4\n")); },
               ErrorCode::kInvalidInput, {"c.csv:2", "column 2", "noon"});
  expect_error([&] { load_flight_tracks_csv(write(dir, "d.csv", header + "A,2013-04-26T12:00:00Z,7,91,1e4\n")); },
               ErrorCode::kInvalidInput, {"d.csv:2", "latitude 91"});
  expect_error([&] { load_flight_tracks_csv(write(dir, "e.csv", header + "A,2013-04-26T12:00:00Z,7,50,nan\n")); },
               ErrorCode::kInvalidInput, {"e.csv:2", "altitude"});
  expect_error([&] { load_flight_tracks_csv(write(dir, "f.csv", header + "A,2013-04-26T12:00:00Z,7,50,1\nA,2013-04-26T12:00:00Z,8,50,1\n")); },
               ErrorCode::kInvalidInput, {"f.csv", "'A'", "same time"});
  expect_error([&] { load_flight_tracks_csv(write(dir, "g.csv", header)); },
               ErrorCode::kInvalidInput, {"g.csv", "no position reports"});
  expect_error([&] { load_flight_tracks_csv(write(dir, "h.csv", header + "A,2013-04-26T12:00:00Z\n")); },
               ErrorCode::kInvalidInput, {"h.csv:2", "2 fields"});
}

}  // namespace
}  // namespace strielad::geo
