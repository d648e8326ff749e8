// SPDX-License-Identifier: Apache-2.0
#include "view/track_window.h"

#include <algorithm>

namespace strielad::view {
namespace {

struct Point {
  double lon, lat, altitude_m;
};

Point at(const geo::FlightTrack& t, std::size_t i) { return {t.lon[i], t.lat[i], t.altitude_m[i]}; }

// Position at time s, with t.seconds[i] <= s <= t.seconds[i + 1].
Point interpolate(const geo::FlightTrack& t, std::size_t i, double s) {
  if (i + 1 >= t.size()) return at(t, i);
  const double f = (s - t.seconds[i]) / (t.seconds[i + 1] - t.seconds[i]);
  return {t.lon[i] + f * (t.lon[i + 1] - t.lon[i]), t.lat[i] + f * (t.lat[i + 1] - t.lat[i]),
          t.altitude_m[i] + f * (t.altitude_m[i + 1] - t.altitude_m[i])};
}

void push(std::vector<float>& out, const lod::WorldFrame& frame, const Point& p) {
  const auto xy = frame.geographic_to_world(p.lon, p.lat);
  out.push_back(static_cast<float>(xy[0]));
  out.push_back(static_cast<float>(xy[1]));
  out.push_back(static_cast<float>(p.altitude_m / 1000.0));
}

}  // namespace

TrackLines window_tracks(const geo::FlightTracks& tracks, double now, double window,
                         const lod::WorldFrame& frame) {
  TrackLines out;
  if (!frame.on_earth()) return out;
  const double from = now - std::max(window, 0.0);
  for (const auto& t : tracks.tracks) {
    if (t.size() == 0 || t.seconds.front() > now || t.seconds.back() < from) continue;
    ++out.tracks_shown;
    // First report after `from`, and the segment [i0, i0 + 1] holding `from`.
    const auto first_after = std::upper_bound(t.seconds.begin(), t.seconds.end(), from);
    const std::size_t i0 = first_after == t.seconds.begin()
                               ? 0
                               : static_cast<std::size_t>(first_after - t.seconds.begin()) - 1;
    const double start = std::max(from, t.seconds.front());
    const double end = std::min(now, t.seconds.back());
    Point previous = interpolate(t, i0, start);
    for (std::size_t i = i0 + 1; i < t.size() && t.seconds[i] < end; ++i) {
      const Point p = at(t, i);
      push(out.segments, frame, previous);
      push(out.segments, frame, p);
      previous = p;
    }
    const auto last = std::upper_bound(t.seconds.begin(), t.seconds.end(), end);
    const std::size_t i1 = static_cast<std::size_t>(last - t.seconds.begin()) - 1;
    const Point head = interpolate(t, i1, end);
    if (end > start) {
      push(out.segments, frame, previous);
      push(out.segments, frame, head);
    }
    if (now <= t.seconds.back()) push(out.heads, frame, head);
  }
  return out;
}

}  // namespace strielad::view
