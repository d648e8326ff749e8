// SPDX-License-Identifier: Apache-2.0
// Flight tracks for the viewer's geographic context (issue 8, "Trajectories"), read
// from CSV: a header row naming the columns id, time, lon, lat, altitude (any order,
// other columns ignored), then one row per position report. `time` is an ISO 8601 UTC
// date-time ("2013-04-26T12:03:00Z"; a zone offset is allowed), `lon`/`lat` degrees,
// `altitude` metres above sea level. Rows of one id need not be adjacent or sorted;
// each track is sorted by time. Times are kept as seconds since the first report.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace strielad::geo {

struct FlightTrack {
  std::string id;
  std::vector<double> seconds;  // since FlightTracks::reference_julian_day, ascending
  std::vector<double> lon, lat, altitude_m;
  std::size_t size() const { return seconds.size(); }
};

struct FlightTracks {
  double reference_julian_day = 0;  // the earliest report, UTC
  std::vector<FlightTrack> tracks;  // in order of first appearance
  std::size_t reports = 0;
};

// \error kNotFound / kIo naming the file; kInvalidInput naming file, line and column for
// a missing column, a malformed or non-finite value, a latitude outside [-90, 90], two
// reports of one track at the same time, or a file without reports.
FlightTracks load_flight_tracks_csv(const std::filesystem::path& path);

}  // namespace strielad::geo
