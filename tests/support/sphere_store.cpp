// SPDX-License-Identifier: Apache-2.0
#include "support/sphere_store.h"

#include <cmath>

#include "convert/converter.h"
#include "lod/world_frame.h"
#include "support/netcdf_fixture.h"

namespace strielad::testing {

std::filesystem::path write_sphere_store(const std::filesystem::path& dir, unsigned brick,
                                         std::size_t samples) {
  const std::size_t n = samples;
  std::vector<double> lon(n), lat(n), height(n);
  for (std::size_t i = 0; i < n; ++i) {
    lon[i] = double(i) / double(n - 1);
    lat[i] = -0.5 + double(i) / double(n - 1);
    height[i] = 11119.5 * double(i) / double(n - 1);
  }
  std::vector<std::filesystem::path> files;
  for (int t = 0; t < 2; ++t) {
    std::vector<double> d1, d2;
    const double shift = t * kSphereStepShiftKm;
    for (std::size_t k = 0; k < n; ++k)
      for (std::size_t j = 0; j < n; ++j)
        for (std::size_t i = 0; i < n; ++i) {
          // The viewer's world frame (lod/world_frame.h) at exaggeration 10.
          const Vec3 p{(lon[i] - 0.5) * lod::kKmPerDegree, lat[j] * lod::kKmPerDegree,
                            height[k] / 1000.0 * 10.0};
          const auto distance = [&](const Vec3& c) {
            return std::sqrt((p[0] - c[0] - shift) * (p[0] - c[0] - shift) +
                             (p[1] - c[1]) * (p[1] - c[1]) + (p[2] - c[2]) * (p[2] - c[2]));
          };
          d1.push_back(distance(kSphereCenter1));
          d2.push_back(distance(kSphereCenter2));
        }
    const auto path = dir / ("spheres_t" + std::to_string(t) + ".nc");
    NetcdfFixture(NC_NETCDF4)
        .coordinate("time", {600.0 * t},
                    {NcAttr::text_value("standard_name", "time"),
                     NcAttr::text_value("units", "seconds since 2013-04-26 12:00:00")},
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
        .variable("d1", NC_FLOAT, {"time", "height", "lat", "lon"}, d1,
                  {NcAttr::text_value("units", "km")})
        .variable("d2", NC_FLOAT, {"time", "height", "lat", "lon"}, d2,
                  {NcAttr::text_value("units", "km")})
        .write(path);
    files.push_back(path);
  }
  build::ConvertOptions options;
  options.inputs = files;
  options.store = dir / "spheres";
  options.brick = brick;
  options.threads = 2;
  build::convert(options);
  return options.store;
}

}  // namespace strielad::testing
