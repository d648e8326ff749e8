// SPDX-License-Identifier: Apache-2.0
// A curvilinear horizontal grid placed by 2-D longitude and latitude arrays (CF auxiliary
// coordinates over the variable's two horizontal dimensions): the checks that make its
// arrays a store's GEOMETRY coordinates (formats/store.md, "Geometry file") and the
// orientation of its index directions on the Earth.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace strielad::ingest {

struct CurvilinearGrid {
  std::string lon_variable, lat_variable;  // the source's 2-D coordinate variables
  std::size_t nx = 0, ny = 0;              // columns (i, along x) and rows (j, along y)
  // ny * nx values, i fastest, as the file holds them in float64; lon unwrapped: no jump
  // of 180 degrees or more between neighbours along i or j.
  std::vector<double> lon, lat;
  // +1 or -1: the sign of the cross product of the (i+1) and (j+1) steps in a local
  // (east, north) frame, the same in every cell.
  int orientation = 1;
  friend bool operator==(const CurvilinearGrid&, const CurvilinearGrid&) = default;
};

// Checks `lon` and `lat` (ny * nx values each, i fastest) and returns the grid with its
// longitudes unwrapped and its orientation. Throws kInvalidInput naming `what` (the file
// and variable), the coordinate variable and the (i, j) at fault when a value is not
// finite or missing (equal to one of `missing`), a latitude lies outside [-90, 90], a grid
// cell contains a pole (or a sample lies on one), the longitudes cannot be unwrapped to
// have no jump of 180 degrees or more between neighbours, or the orientation changes
// between cells (the grid folds) or vanishes; also when the grid has fewer than 2 x 2
// samples.
CurvilinearGrid make_curvilinear_grid(std::string lon_variable, std::string lat_variable,
                                      std::size_t nx, std::size_t ny, std::vector<double> lon,
                                      std::vector<double> lat,
                                      const std::vector<double>& lon_missing,
                                      const std::vector<double>& lat_missing,
                                      std::string_view what);

// nullopt when `got` equals `want` value for value (names included); else the first
// difference: "2-D coordinate 'lon' at (i 3, j 1) is 12.5 but <want_where> has 12.25".
std::optional<std::string> curvilinear_difference(const CurvilinearGrid& got,
                                                  const CurvilinearGrid& want,
                                                  std::string_view want_where);

}  // namespace strielad::ingest
