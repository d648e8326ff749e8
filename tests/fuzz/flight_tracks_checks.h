// SPDX-License-Identifier: Apache-2.0
// What every loaded FlightTracks must satisfy (scenery/flight_tracks.h); the flight-track
// fuzz targets abort when a reader returns anything else.
#pragma once

#include <cmath>
#include <cstdlib>

#include "scenery/flight_tracks.h"

namespace strielad::fuzz {

inline void check_flight_tracks(const geo::FlightTracks& t) {
  std::size_t reports = 0;
  for (const auto& track : t.tracks) {
    const std::size_t n = track.seconds.size();
    if (n == 0 || track.lon.size() != n || track.lat.size() != n || track.altitude_m.size() != n) {
      std::abort();
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(track.seconds[i]) || track.seconds[i] < 0 ||
          (i > 0 && !(track.seconds[i] >= track.seconds[i - 1])) || !(std::abs(track.lat[i]) <= 90)) {
        std::abort();
      }
    }
    reports += n;
  }
  if (reports != t.reports || !std::isfinite(t.reference_julian_day)) std::abort();
}

}  // namespace strielad::fuzz
