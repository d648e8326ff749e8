// SPDX-License-Identifier: Apache-2.0
#include "support/globe_store.h"

#include <cmath>
#include <numbers>
#include <vector>

#include "convert/converter.h"
#include "support/netcdf_fixture.h"

namespace strielad::testing {

std::filesystem::path write_globe_store(const std::filesystem::path& dir,
                                        const std::string& time_units, std::size_t nx,
                                        std::size_t ny, std::size_t nz) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  std::vector<double> lon(nx), lat(ny), height(nz);
  for (std::size_t i = 0; i < nx; ++i) lon[i] = 360.0 * double(i) / double(nx);
  for (std::size_t j = 0; j < ny; ++j) lat[j] = -90.0 + 180.0 * double(j) / double(ny - 1);
  for (std::size_t k = 0; k < nz; ++k) height[k] = 15000.0 * double(k) / double(nz - 1);
  std::vector<double> h, clw;
  for (std::size_t k = 0; k < nz; ++k) {
    for (std::size_t j = 0; j < ny; ++j) {
      for (std::size_t i = 0; i < nx; ++i) {
        h.push_back(height[k] / 1000.0);
        // Blobs: a wave in longitude along three latitude bands, at mid heights.
        const double band = std::exp(-std::pow((std::fabs(lat[j]) - 45.0) / 12.0, 2)) +
                            std::exp(-std::pow(lat[j] / 8.0, 2));
        const double wave = 0.5 + 0.5 * std::sin(5.0 * lon[i] * kDeg + 0.05 * lat[j]);
        const double level = std::exp(-std::pow((height[k] - 5500.0) / 2500.0, 2));
        clw.push_back(1e-4 * band * wave * level);
      }
    }
  }
  const auto path = dir / "globe.nc";
  NetcdfFixture(NC_NETCDF4)
      .coordinate("time", {0.0},
                  {NcAttr::text_value("standard_name", "time"),
                   NcAttr::text_value("units", time_units)},
                  NC_DOUBLE, true)
      .coordinate("height", height,
                  {NcAttr::text_value("standard_name", "height"),
                   NcAttr::text_value("units", "m"), NcAttr::text_value("positive", "up")})
      .coordinate("lat", lat,
                  {NcAttr::text_value("standard_name", "latitude"),
                   NcAttr::text_value("units", "degrees_north")})
      .coordinate("lon", lon,
                  {NcAttr::text_value("standard_name", "longitude"),
                   NcAttr::text_value("units", "degrees_east")})
      .variable("height_km", NC_FLOAT, {"time", "height", "lat", "lon"}, h,
                {NcAttr::text_value("units", "km")})
      .variable("clw", NC_FLOAT, {"time", "height", "lat", "lon"}, clw,
                {NcAttr::text_value("units", "kg kg-1")})
      .write(path);
  build::ConvertOptions options;
  options.inputs = {path};
  options.store = dir / "globe";
  options.brick = 8;
  options.threads = 2;
  build::convert(options);
  return options.store;
}

}  // namespace strielad::testing
