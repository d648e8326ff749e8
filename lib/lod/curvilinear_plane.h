// SPDX-License-Identifier: Apache-2.0
// A curvilinear grid's columns on the world frame's plane (lod/world_frame.h): the plane
// tangent at (lon0, lat0) is affine in longitude and latitude (x = (lon - lon0) K cos lat0,
// y = (lat - lat0) K), so the bilinear interpolation of the stored longitudes and
// latitudes between four columns (format/curvilinear_lonlat.h, the store format's
// definition) is the bilinear interpolation of the columns' plane positions. A grid
// cell's edges are straight on the plane and the cell lies inside its corners' hull.
//
// Positions are fractional level-0 indices (i, j): a curvilinear store's x and y axes
// are index axes with values 0, 1, ..., n - 1. Outside [0, nx - 1] x [0, ny - 1] the
// nearest cell's bilinear map is continued, as CurvilinearLonLat continues it.
//
// The inverse (plane to index) finds the cell that holds the point through a bucket
// grid over the cells' boxes, then solves the cell's bilinear map by Newton's method;
// beyond the grid it solves the continued map of a boundary cell near the point, the one
// whose continuation `position` uses at the solution.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "format/curvilinear_lonlat.h"
#include "format/geometry_file_format.h"
#include "octree/octree_layout.h"

namespace strielad::lod {

class CurvilinearPlane {
 public:
  // The columns of `coordinates` on the plane tangent at (lon0, lat0) with `km_per_lon`
  // kilometres per degree of longitude; longitudes are taken the short way round from
  // lon0. `what` names the coordinates in errors.
  // \error kInvalidArgument when the coordinates are not at least 2 x 2 or their arrays
  // do not hold nx * ny values.
  // \error kUnsupported naming the columns when neighbours lie on both sides of the
  // meridian opposite lon0 (the grid goes round a pole or the whole Earth) or when the
  // grid folds over itself on the plane (cells of both orientations).
  CurvilinearPlane(const format::HorizontalCoordinates& coordinates, double lon0, double lat0,
                   double km_per_lon, const std::string& what);

  std::size_t nx() const { return nx_; }
  std::size_t ny() const { return ny_; }
  // Plane km of column (i, j).
  const std::array<double, 2>& at(std::size_t i, std::size_t j) const { return xy_[j * nx_ + i]; }
  // Plane km at fractional index (i, j).
  std::array<double, 2> position(double i, double j) const;
  // {dX/di, dX/dj, dY/di, dY/dj} at (i, j), in the cell `position` uses (on an edge, the
  // cell above it; the last cell at the far end).
  std::array<double, 4> jacobian(double i, double j) const;
  // The fractional index of plane point (x, y); NaN when no cell's map reaches it (beyond
  // the grid: the continued maps of the 16 boundary cells nearest to it do not).
  std::array<double, 2> index_of(double x, double y) const;
  // +1 or -1: the sign of every cell's determinant (the constructor refuses a mix).
  int orientation() const { return orientation_; }
  // {x lo, y lo, x hi, y hi} of the columns in the index box's horizontal extent: the
  // box of every point the box's cells place (their edges are straight).
  std::array<double, 4> box_of(const IndexBox& box) const;

 private:
  CellCorners corners(std::size_t i0, std::size_t j0) const;
  // Solves cell (i0, j0)'s bilinear map for (x, y) from the cell's centre; the fractions
  // when it converges.
  bool solve(std::size_t i0, std::size_t j0, double x, double y, double& s, double& t) const;
  void check_tears(double lon0, double km_per_lon, const std::string& what) const;
  void find_orientation(const std::string& what);
  void build_buckets();

  std::size_t nx_ = 0, ny_ = 0;
  std::vector<std::array<double, 2>> xy_;  // column (i, j) at j * nx + i
  int orientation_ = 1;
  // Bucket grid over the plane box of the columns: the cells (i0 + j0 * nx) whose box
  // meets each bucket.
  std::array<double, 4> extent_{};  // x lo, y lo, x hi, y hi
  std::size_t bx_ = 1, by_ = 1;
  double bucket_w_ = 1, bucket_h_ = 1;
  std::vector<std::size_t> bucket_start_;    // bucket b's cells: [start[b], start[b + 1])
  std::vector<std::uint32_t> bucket_cells_;
  std::vector<std::uint32_t> boundary_cells_;
  std::vector<std::array<double, 2>> boundary_centres_;  // plane km of each one's centre
};

}  // namespace strielad::lod
