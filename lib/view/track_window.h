// SPDX-License-Identifier: Apache-2.0
// What the viewer draws of flight tracks at a moment: for
// each track, the part flown during the last `window` seconds before `now` as line
// segments, cut at both ends by linear interpolation between reports, and the
// aircraft's position at `now` when the track spans it. A track that ended before the
// window or starts after `now` shows nothing.
// On the plane: world frame km at exaggeration 1 (z = altitude in km), like the meshes,
// which the renderer scales; each position placed by its true longitude and latitude
// (lod::WorldFrame::geographic_to_world, through the grid mapping's plane on a mapped
// grid), interpolated linearly in longitude/latitude between reports.
// On the globe (WorldFrame::globe()): ECEF km with the frame's exaggeration placed, as
// the globe's meshes and terrain are (WorldFrame::place_geographic at the altitude times
// the exaggeration, along the ellipsoid normal; the renderer scales nothing). Positions
// between reports follow the great circle between them (spherical interpolation of their
// directions, altitude linear), and a segment spanning more than kGlobeTrackStepDeg is
// cut into pieces that short, so that a long leg's chord does not cut below the curved
// surface (at 0.5 degrees a chord sags 60 m under its ends).
#pragma once

#include <cstddef>
#include <vector>

#include "scenery/flight_tracks.h"
#include "lod/world_frame.h"

namespace strielad::view {

inline constexpr double kDefaultTrackWindowSeconds = 120;
// The longest piece of a track line on the globe, degrees of arc.
inline constexpr double kGlobeTrackStepDeg = 0.5;

struct TrackLines {
  std::vector<float> segments;  // pairs of points (x, y, z) for GL_LINES
  // On the globe a leg between reports may be several segments (kGlobeTrackStepDeg).
  std::vector<float> heads;     // one point (x, y, z) per aircraft in the air at `now`
  std::size_t tracks_shown = 0;
  std::size_t segment_count() const { return segments.size() / 6; }
  std::size_t head_count() const { return heads.size() / 3; }
};

// `now` in seconds since tracks.reference_julian_day. Needs a frame on the Earth
// (longitude/latitude axes or a grid mapping); a Cartesian frame gets nothing (the
// viewer refuses tracks on it before: WorldFrame::no_earth_reason). A window <= 0 shows
// only the heads.
TrackLines window_tracks(const geo::FlightTracks& tracks, double now, double window,
                         const lod::WorldFrame& frame);

}  // namespace strielad::view
