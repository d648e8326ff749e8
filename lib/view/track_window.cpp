// SPDX-License-Identifier: Apache-2.0
#include "view/track_window.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strielad::view {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct Point {
  double lon, lat, altitude_m;
};

// A direction from the Earth's centre (the unit sphere) and back; the great circle between
// two positions is the arc between their directions.
Vec3 direction_of(const Point& p) {
  const double cl = std::cos(p.lat * kDeg);
  return {cl * std::cos(p.lon * kDeg), cl * std::sin(p.lon * kDeg), std::sin(p.lat * kDeg)};
}

// The angle between two positions' directions (radians, 0..pi).
double arc(const Vec3& a, const Vec3& b) {
  const Vec3 c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  return std::atan2(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]),
                    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
}

// The position a fraction f of the way from a to b: linear in longitude/latitude on the
// plane, along the great circle on the globe (the altitude linear on both).
Point between(const Point& a, const Point& b, double f, bool globe) {
  const double altitude = a.altitude_m + f * (b.altitude_m - a.altitude_m);
  if (!globe) return {a.lon + f * (b.lon - a.lon), a.lat + f * (b.lat - a.lat), altitude};
  const Vec3 u = direction_of(a), v = direction_of(b);
  const double w = arc(u, v);
  // Linear below a microradian (and for antipodes, whose great circle is undefined).
  double wa = 1.0 - f, wb = f;
  if (w > 1e-6 && w < std::numbers::pi - 1e-6) {
    wa = std::sin((1.0 - f) * w) / std::sin(w);
    wb = std::sin(f * w) / std::sin(w);
  }
  const Vec3 d{wa * u[0] + wb * v[0], wa * u[1] + wb * v[1], wa * u[2] + wb * v[2]};
  const double lat = std::atan2(d[2], std::hypot(d[0], d[1])) / kDeg;
  // At a pole the longitude is any: keep the nearer report's.
  const double lon = std::hypot(d[0], d[1]) > 1e-12 ? std::atan2(d[1], d[0]) / kDeg
                                                    : (f < 0.5 ? a.lon : b.lon);
  return {lon, lat, altitude};
}

Point at(const geo::FlightTrack& t, std::size_t i) { return {t.lon[i], t.lat[i], t.altitude_m[i]}; }

// Position at time s, with t.seconds[i] <= s <= t.seconds[i + 1].
Point interpolate(const geo::FlightTrack& t, std::size_t i, double s, bool globe) {
  if (i + 1 >= t.size()) return at(t, i);
  const double f = (s - t.seconds[i]) / (t.seconds[i + 1] - t.seconds[i]);
  return between(at(t, i), at(t, i + 1), f, globe);
}

class Placer {
 public:
  explicit Placer(const lod::WorldFrame& frame) : frame_(frame), globe_(frame.globe()) {}
  bool globe() const { return globe_; }

  void point(std::vector<float>& out, const Point& p) const {
    if (globe_) {
      const Vec3 w =
          frame_.place_geographic(p.lon, p.lat, p.altitude_m / 1000.0 * frame_.vertical_exaggeration());
      out.insert(out.end(), {static_cast<float>(w[0]), static_cast<float>(w[1]),
                             static_cast<float>(w[2])});
      return;
    }
    const auto xy = frame_.geographic_to_world(p.lon, p.lat);
    out.insert(out.end(), {static_cast<float>(xy[0]), static_cast<float>(xy[1]),
                           static_cast<float>(p.altitude_m / 1000.0)});
  }

  // The line from a to b: one segment on the plane; on the globe, pieces of at most
  // kGlobeTrackStepDeg along the great circle.
  void line(std::vector<float>& out, const Point& a, const Point& b) const {
    std::size_t pieces = 1;
    if (globe_) {
      const double degrees = arc(direction_of(a), direction_of(b)) / kDeg;
      pieces = static_cast<std::size_t>(std::clamp(std::ceil(degrees / kGlobeTrackStepDeg), 1.0,
                                                   180.0 / kGlobeTrackStepDeg));
    }
    Point from = a;
    for (std::size_t k = 1; k <= pieces; ++k) {
      const Point to = k == pieces ? b : between(a, b, double(k) / double(pieces), true);
      point(out, from);
      point(out, to);
      from = to;
    }
  }

 private:
  const lod::WorldFrame& frame_;
  bool globe_;
};

}  // namespace

TrackLines window_tracks(const geo::FlightTracks& tracks, double now, double window,
                         const lod::WorldFrame& frame) {
  TrackLines out;
  if (!frame.on_earth()) return out;
  const Placer place(frame);
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
    Point previous = interpolate(t, i0, start, place.globe());
    for (std::size_t i = i0 + 1; i < t.size() && t.seconds[i] < end; ++i) {
      const Point p = at(t, i);
      place.line(out.segments, previous, p);
      previous = p;
    }
    const auto last = std::upper_bound(t.seconds.begin(), t.seconds.end(), end);
    const std::size_t i1 = static_cast<std::size_t>(last - t.seconds.begin()) - 1;
    const Point head = interpolate(t, i1, end, place.globe());
    if (end > start) place.line(out.segments, previous, head);
    if (now <= t.seconds.back()) place.point(out.heads, head);
  }
  return out;
}

}  // namespace strielad::view
