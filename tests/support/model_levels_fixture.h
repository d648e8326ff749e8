// SPDX-License-Identifier: Apache-2.0
// Small netCDF files on terrain-following model levels for the vertical geometry tests:
// a (time, lev, lat, lon) grid whose lev coordinate carries the attributes a test gives,
// a data variable T, and helpers for the per-sample values of height and term fields.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "support/netcdf_fixture.h"

namespace strielad::testing {

struct ModelLevels {
  std::size_t nt = 2, nz = 3, ny = 3, nx = 4;
  std::vector<double> lon{0.0, 10.0, 20.0, 30.0};  // regional: not round the Earth
  std::vector<NcAttr> lev_attrs{NcAttr::text_value("axis", "Z"),
                                NcAttr::text_value("long_name", "model level")};

  std::size_t plane() const { return ny * nx; }
  // time, lev, lat, lon coordinates and T(time, lev, lat, lon).
  NetcdfFixture fixture(int cmode = NC_NETCDF4) const {
    NetcdfFixture f(cmode);
    std::vector<double> lev, lat;
    for (std::size_t k = 0; k < nz; ++k) lev.push_back(static_cast<double>(k + 1));
    for (std::size_t j = 0; j < ny; ++j) lat.push_back(10.0 * static_cast<double>(j));
    f.coordinate("time", ramp(nt),
                 {NcAttr::text_value("standard_name", "time"),
                  NcAttr::text_value("units", "hours since 2000-01-01")},
                 NC_DOUBLE, true)
        .coordinate("lev", lev, lev_attrs)
        .coordinate("lat", lat,
                    {NcAttr::text_value("standard_name", "latitude"),
                     NcAttr::text_value("units", "degrees_north")})
        .coordinate("lon", lon,
                    {NcAttr::text_value("standard_name", "longitude"),
                     NcAttr::text_value("units", "degrees_east")})
        .variable("T", NC_FLOAT, {"time", "lev", "lat", "lon"}, ramp(nt * nz * ny * nx, 250.0),
                  {NcAttr::text_value("units", "K")});
    return f;
  }
};

// value(t, k, s) for t < nt, k < nz, s < plane, in that order (s fastest).
template <typename F>
std::vector<double> field(std::size_t nt, std::size_t nz, std::size_t plane, F&& value) {
  std::vector<double> out;
  for (std::size_t t = 0; t < nt; ++t) {
    for (std::size_t k = 0; k < nz; ++k) {
      for (std::size_t s = 0; s < plane; ++s) out.push_back(value(t, k, s));
    }
  }
  return out;
}

}  // namespace strielad::testing
