// SPDX-License-Identifier: Apache-2.0
// Runs a grid mapping's PROJ pipeline (geo/cf_grid_mapping.h): a grid's axis
// coordinates to geographic longitude and latitude in degrees, and back. The one
// mechanism that places data, domain boxes, output frames and the viewer on a mapped
// grid.
//
// PROJ objects are not shared between threads: each thread makes its own
// GridProjection (making one costs a few tens of microseconds; transform many points
// with it). An empty pipeline is the identity (a grid on longitude and latitude).
#pragma once

#include <array>
#include <memory>
#include <string>
#include <string_view>

namespace strielad::geo {

class GridProjection {
 public:
  // \error kUnsupported quoting the pipeline and PROJ's message when PROJ rejects it.
  explicit GridProjection(std::string_view pipeline);
  ~GridProjection();
  GridProjection(GridProjection&&) noexcept;
  GridProjection& operator=(GridProjection&&) noexcept;

  // This thread's projection for `pipeline`, made on first use and kept for the
  // thread's life (for code that many threads run over one store).
  static const GridProjection& for_this_thread(const std::string& pipeline);

  bool identity() const { return impl_ == nullptr; }

  // Axis (x, y) to (longitude, latitude) in degrees; longitudes as PROJ gives them (its
  // default range is -180..180). NaN, NaN where the point has no geographic position
  // (outside the projection's domain).
  std::array<double, 2> to_geographic(double x, double y) const;
  // (longitude, latitude) in degrees to axis (x, y); NaN, NaN where it has none.
  std::array<double, 2> to_axis(double lon, double lat) const;

  // The Jacobian of to_geographic at (x, y) by central differences of step h (axis
  // units): {dlon/dx, dlon/dy, dlat/dx, dlat/dy} in degrees per axis unit, longitude
  // differences taken the short way round. Relative error about (h / scale)^2 of the
  // map; NaN where a sample point has no position.
  std::array<double, 4> jacobian(double x, double y, double h) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace strielad::geo
