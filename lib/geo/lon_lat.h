// SPDX-License-Identifier: Apache-2.0
// A geographic position: longitude and latitude in degrees (WGS84 as models and their
// users treat them: geo/cf_grid_mapping.h), as the DEM and drape readers hand them on.
#pragma once

namespace strielad::geo {

struct LonLat {
  double lon = 0, lat = 0;  // degrees
};

}  // namespace strielad::geo
