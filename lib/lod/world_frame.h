// SPDX-License-Identifier: Apache-2.0
// The world frame the viewer renders in and the level-of-detail cut measures in: a
// right-handed frame in kilometres, x east, y north, z up, origin at the domain's
// horizontal centre and height 0 (sea level or ground, as the height axis says).
//
// Dataset axis coordinates (format::Manifest axes x, y, z) map axis by axis, each map
// monotonic, so the world box of a block of samples is spanned by its corner samples:
// - geographic x/y (longitude/latitude in degrees): an equirectangular plane tangent at
//   the domain centre (lon0, lat0): x = (lon - lon0) * K * cos(lat0), y = (lat - lat0) * K
//   with K = 111.195 km per degree (R = 6371.0088 km, the IUGG mean radius, as the
//   "metric" output frame of formats/scene.md). lon0/lat0 are the midpoints of the
//   axes' ranges.
// - metric x/y (units m or km, e.g. a projected grid): kilometres from the range midpoint.
// - height (m or km; no units means metres): z = height_km * vertical_exaggeration.
// - pressure (Pa, hPa, mbar, kPa, bar, atm): the ICAO standard atmosphere height of the
//   pressure (geo/standard_atmosphere.h), then as height.
// Descending axes (latitude north to south, height top down, pressure) map the same way:
// world coordinates do not depend on storage order.
#pragma once

#include <array>
#include <cstddef>
#include <numbers>
#include <vector>

#include "format/manifest.h"
#include "lod/geometry.h"
#include "octree/octree_layout.h"

namespace strielad::lod {

// Atmospheric domains are flat: the paper's grid spans about 700 x 780 km horizontally
// and 21 km vertically, so at true scale its whole depth is 3% of its width and clouds
// are slivers in any view that shows the domain. Ten times lifts the 0-12 km cloud layer
// to about a sixth of the width, still flat enough that horizontal structure reads
// as a map. One number for all data sets so that views and camera paths compare.
inline constexpr double kDefaultVerticalExaggeration = 10.0;

// Kilometres per degree of latitude (and of longitude at the equator).
inline constexpr double kKmPerDegree = 6371.0088 * std::numbers::pi / 180.0;

struct WorldFrameOptions {
  double vertical_exaggeration = kDefaultVerticalExaggeration;  // finite, > 0
};

enum class HorizontalMap { kGeographic, kMetric };
enum class VerticalMap { kHeight, kPressure };

class WorldFrame {
 public:
  // \error kUnsupported naming the axis for axes without a world position: x/y neither
  // longitude/latitude nor in length units; a vertical axis that is neither height nor
  // pressure (model levels, depth, unknown), or has units it cannot convert.
  // \error kInvalidInput for empty, non-finite or non-monotonic axis values (as
  // check_axis_values) and for a pressure axis with a value <= 0.
  // \error kInvalidArgument for a vertical exaggeration that is not finite and > 0.
  explicit WorldFrame(const format::Manifest& manifest, WorldFrameOptions options = {});

  // Axis coordinates (x, y, z of the manifest, in the axes' own units) to world km.
  // Pressures <= 0 give NaN in z (callers check them: camera_path.h does).
  Vec3 to_world(const Vec3& axis) const;
  // World km back to axis coordinates (the exact inverse up to rounding).
  Vec3 to_axis(const Vec3& world) const;
  double axis_to_world(int axis, double value) const;
  double world_to_axis(int axis, double world) const;

  // World coordinate of level-0 sample `index` along `axis` (precomputed).
  double sample_world(int axis, std::size_t index) const { return samples_[axis][index]; }
  Dims3 dims() const { return dims_; }
  // The box spanned by all samples.
  const WorldBox& domain() const { return domain_; }

  HorizontalMap horizontal() const { return horizontal_; }
  VerticalMap vertical() const { return vertical_; }
  double vertical_exaggeration() const { return exaggeration_; }
  // Axis-unit value of the origin along x and y (lon0/lat0 for geographic frames).
  double origin(int axis) const { return origin_[axis]; }
  // World km per axis unit along x or y (geographic: per degree, longitude at lat0).
  double km_per_unit(int axis) const { return km_per_unit_[axis]; }
  // Metres (height) or pascals (pressure) per unit of the vertical axis.
  double vertical_unit() const { return vertical_unit_; }

 private:
  HorizontalMap horizontal_ = HorizontalMap::kGeographic;
  VerticalMap vertical_ = VerticalMap::kHeight;
  double exaggeration_ = kDefaultVerticalExaggeration;
  std::array<double, 2> origin_{};  // axis units
  std::array<double, 2> km_per_unit_{};
  double vertical_unit_ = 1.0;      // metres (height) or pascals (pressure) per axis unit
  Dims3 dims_;
  std::array<std::vector<double>, 3> samples_;
  WorldBox domain_;
};

// The world box of every octree node, indexed by NodeId: spanned by the node's brick's
// corner samples (OctreeLayout::fine_box), so a child's box lies inside its parent's and
// neighbours share faces.
// \error kInvalidArgument when the layout's grid is not the frame's dims.
std::vector<WorldBox> node_world_boxes(const OctreeLayout& layout, const WorldFrame& frame);

}  // namespace strielad::lod
