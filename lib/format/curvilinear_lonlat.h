// SPDX-License-Identifier: Apache-2.0
// Where a fractional index position (i, j) of a curvilinear grid lies (formats/store.md,
// "Grid geometry (version 5)"): the bilinear interpolation of the longitudes and
// latitudes of the four level-0 columns around it, from the store's GEOMETRY file. The
// longitudes there are unwrapped (no jump of half a turn between neighbours), so a cell
// never straddles a seam of the interpolation. A position is a pure function of (i, j):
// vertices that neighbouring nodes share get the same bits.
#pragma once

#include <array>
#include <memory>

#include "format/geometry_file_format.h"

namespace strielad {

// Where fractional index (i, j) lies among a grid's nx x ny columns: the cell (i0, j0)
// (clamped to the grid's cells, so positions beyond it continue the edge cell; on a cell
// edge, the cell above it) and the fractions (s, t) within it.
struct GridCell {
  std::size_t i0 = 0, j0 = 0;
  double s = 0, t = 0;
};
GridCell grid_cell(double i, double j, std::size_t nx, std::size_t ny);

// A cell's corners (i0, j0), (i0 + 1, j0), (i0, j0 + 1), (i0 + 1, j0 + 1), two
// components each.
using CellCorners = std::array<std::array<double, 2>, 4>;
// The bilinear interpolation of the corners at fractions (s, t), and its derivatives
// {d0/ds, d0/dt, d1/ds, d1/dt}.
std::array<double, 2> bilinear(const CellCorners& p, double s, double t);
std::array<double, 4> bilinear_jacobian(const CellCorners& p, double s, double t);

class CurvilinearLonLat {
 public:
  // \error kInvalidArgument when the coordinates are not at least 2 x 2 or their arrays
  // do not hold nx * ny values.
  explicit CurvilinearLonLat(std::shared_ptr<const format::HorizontalCoordinates> coordinates);

  // Longitude (unwrapped, as stored) and latitude in degrees at (i, j); positions outside
  // [0, nx - 1] x [0, ny - 1] are extrapolated from the nearest cell.
  std::array<double, 2> at(double i, double j) const;
  // The bilinear map's derivatives at (i, j): {dlon/di, dlon/dj, dlat/di, dlat/dj}, in
  // the cell `at` uses (on a cell edge, the cell above it; the last cell at the far end).
  std::array<double, 4> jacobian(double i, double j) const;
  // The position at the grid's centre index ((nx - 1) / 2, (ny - 1) / 2).
  std::array<double, 2> centre() const;
  // The sign of the map's determinant at the centre (east and north against i and j),
  // +1 or -1; the converter refuses grids whose sign changes.
  int orientation() const;

 private:
  CellCorners corners(const GridCell& c) const;

  std::shared_ptr<const format::HorizontalCoordinates> c_;
};

}  // namespace strielad
