// SPDX-License-Identifier: Apache-2.0
// Synthetic flight tracks over the sample domain ("27,000 tracks at
// interactive frame rates", measured on a generated scene). Deterministic from the seed: each
// aircraft flies a straight line across the domain at 200-250 m/s, at a cruise level
// of 9-12.5 km, or climbing from or descending to the ground near the domain's
// airports; every aircraft is in the air during the whole span (flights of 20 to 50
// minutes, take-offs spread before it), so all of them are on screen at any time of it. One report a minute, in the
// CSV format of scenery/flight_tracks.h (id, time, lon, lat, altitude).
#pragma once

#include <cstdint>
#include <filesystem>

namespace strielad::synthetic {

struct SampleTrackSpec {
  std::size_t tracks = 27000;
  double span_seconds = 900;    // from 12:00 UTC (the sample's first step)
  std::uint64_t seed = 1;
  double report_seconds = 60;
};

struct SampleTracksResult {
  std::size_t tracks = 0, reports = 0;
  std::uint64_t bytes = 0;
};

// Writes `path` atomically. \error kInvalidArgument for 0 tracks, more than 10 M, or a
// span or report interval that is not finite and > 0; kIo when it cannot be written.
SampleTracksResult write_sample_tracks(const SampleTrackSpec& spec, const std::filesystem::path& path);

}  // namespace strielad::synthetic
