// SPDX-License-Identifier: Apache-2.0
// Flight tracks for the viewer's geographic context (aircraft trajectories), read
// from CF-NetCDF trajectory files (below) or from CSV: a header row naming the columns id, time, lon, lat, altitude (any order,
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

// A CF trajectory file (featureType "trajectory"): time, longitude, latitude and
// altitude variables found by standard_name (or the names time, lon, lat, alt), over
// (trajectory, obs) with _FillValue padding or over one sample dimension with a
// row_size variable (sample_dimension attribute); ids from the variable with cf_role
// trajectory_id (numbers or text), else the track's index; altitude in m, km or ft.
// \error kNotFound / kIo / kInvalidInput naming the file for an unreadable file, a
// missing variable, mismatched shapes, bad row sizes or a latitude outside [-90, 90];
// kUnsupported for other altitude units or a model calendar.
FlightTracks load_flight_tracks_netcdf(const std::filesystem::path& path);

// NetCDF for .nc, .nc4, .netcdf, .cdf; CSV otherwise.
FlightTracks load_flight_tracks(const std::filesystem::path& path);

// \error kNotFound / kIo naming the file; kInvalidInput naming file, line and column for
// a missing column, a malformed or non-finite value, a latitude outside [-90, 90], two
// reports of one track at the same time, or a file without reports.
FlightTracks load_flight_tracks_csv(const std::filesystem::path& path);

}  // namespace strielad::geo
