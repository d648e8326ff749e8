// SPDX-License-Identifier: Apache-2.0
// The vertical exaggeration strielad-view starts with when none is given (docs/view.md,
// "Defaults for any domain"): it follows the domain's extents, so that the default view
// shows depth whatever the domain. The exaggerated depth is kExaggeratedDepthShare of
// the domain's horizontal size (the geometric mean of its width and length):
//
//   E = kExaggeratedDepthShare * sqrt(width * length) / depth
//
// rounded to the nearest of 1, 2 and 5 times a power of ten (nearest by ratio, as map
// scales and axis ticks are chosen, so domains of about the same shape get the same
// number and their views compare), then clamped to [kMinDefaultExaggeration,
// kMaxDefaultExaggeration]. The paper's grid (about 700 x 780 km, 21 km deep) gives
// 0.28 * 738 / 21 = 9.8, so 10 (lod::kDefaultVerticalExaggeration, the number camera
// paths assume); a global grid (about 40,000 x 20,000 km, 31 km deep to 10 hPa) gives
// 255, so 200; a 10 km wide, 5 km deep large-eddy domain stays at true scale (1).
#pragma once

#include <string>

#include "lod/world_frame.h"

namespace strielad::view {

inline constexpr double kExaggeratedDepthShare = 0.28;
inline constexpr double kMinDefaultExaggeration = 1.0;     // never flatter than true scale
inline constexpr double kMaxDefaultExaggeration = 1000.0;
// On the globe (lod/world_frame.h) the default is at most this: a 30 km deep atmosphere
// becomes a shell 600 km thick, a tenth of the Earth's radius, instead of the plane's
// 200 for a global domain, which would lift it by the Earth's radius.
inline constexpr double kMaxGlobeDefaultExaggeration = 20.0;

// A domain's size in true kilometres (no exaggeration).
struct DomainExtent {
  double width_km = 0;   // west to east (world x)
  double length_km = 0;  // south to north (world y)
  double depth_km = 0;   // lowest to highest level (world z / exaggeration)
};

// The domain box of `frame` in true kilometres, whatever the frame's exaggeration.
DomainExtent domain_extent(const lod::WorldFrame& frame);

// The rule above. A domain without horizontal extent or without depth (a single level),
// or with extents that are not finite, gets lod::kDefaultVerticalExaggeration.
double default_vertical_exaggeration(const DomainExtent& extent);

// "200 for a 39822 x 19696 km domain 30.9 km deep (0.28 x horizontal size / depth =
// 253, rounded to 1-2-5)": what the rule chose and why, for the log.
std::string describe_default_exaggeration(const DomainExtent& extent);

}  // namespace strielad::view
