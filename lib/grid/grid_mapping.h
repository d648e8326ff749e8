// SPDX-License-Identifier: Apache-2.0
// The horizontal placement of a grid whose x and y axes are map-projection coordinates
// (CF `grid_mapping`, conventions appendix F): the grid-mapping variable's attributes as
// the source wrote them, and the PROJ pipeline derived from them that turns axis
// coordinates into geographic longitude and latitude (geo/cf_grid_mapping.h builds it,
// geo/grid_projection.h runs it). Recorded in the store manifest (formats/store.md,
// "Grid mapping").
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace strielad {

struct GridMapping {
  std::string variable;  // the grid-mapping variable in the source, e.g. "rotated_pole"
  std::string name;      // its grid_mapping_name, e.g. "rotated_latitude_longitude"
  // Every attribute of the grid-mapping variable: a number, an array of numbers (two
  // standard parallels) or text, keyed by attribute name.
  nlohmann::json attributes = nlohmann::json::object();
  // PROJ pipeline from (x, y) in the axes' own units to (longitude, latitude) in degrees.
  std::string proj;

  friend bool operator==(const GridMapping&, const GridMapping&) = default;
};

}  // namespace strielad
