// SPDX-License-Identifier: Apache-2.0
#include "synthetic/wrf_grid.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "geo/grid_projection.h"
#include "synthetic/sample_grid.h"

namespace strielad::synthetic {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

// PROJ's pipeline from projected metres to longitude/latitude in degrees.
std::string inverse_pipeline(const std::string& proj) {
  return fmt::format("+proj=pipeline +step +inv {} +step +proj=unitconvert +xy_in=rad +xy_out=deg",
                     proj);
}

// The cone factor of a Lambert conformal projection with true latitudes 30 and 60.
double cone_factor() {
  const double p1 = kWrfTrueLat1 * kRadPerDeg, p2 = kWrfTrueLat2 * kRadPerDeg;
  return std::log(std::cos(p1) / std::cos(p2)) /
         std::log(std::tan(std::numbers::pi / 4 + p2 / 2) / std::tan(std::numbers::pi / 4 + p1 / 2));
}

void place(const geo::GridProjection& projection, const WrfGrid& g, std::size_t nx, std::size_t ny,
           double i0, double j0, std::vector<double>& lon, std::vector<double>& lat) {
  lon.resize(nx * ny);
  lat.resize(nx * ny);
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const auto p = projection.to_geographic(g.x_at(static_cast<double>(i) + i0),
                                              g.y_at(static_cast<double>(j) + j0));
      lon[j * nx + i] = p[0];
      lat[j * nx + i] = p[1];
    }
  }
}

}  // namespace

std::string wrf_lcc_proj_string(double cen_lat, double stand_lon) {
  return fmt::format("+proj=lcc +lat_1={} +lat_2={} +lat_0={} +lon_0={} +R={} +units=m",
                     kWrfTrueLat1, kWrfTrueLat2, cen_lat, stand_lon, kWrfEarthRadius);
}

double WrfGrid::x_at(double i) const { return (i - 0.5 * static_cast<double>(nx - 1)) * dx; }
double WrfGrid::y_at(double j) const { return (j - 0.5 * static_cast<double>(ny - 1)) * dy; }

WrfGrid wrf_grid(std::size_t nx, std::size_t ny) {
  WrfGrid g;
  g.nx = nx;
  g.ny = ny;
  g.cen_lat = 0.5 * (kLatMin + kLatMax);
  g.cen_lon = 0.5 * (kLonMin + kLonMax);
  const double metres_per_degree = kWrfEarthRadius * kRadPerDeg;
  const double width = (kLonMax - kLonMin) * metres_per_degree * std::cos(g.cen_lat * kRadPerDeg);
  const double height = (kLatMax - kLatMin) * metres_per_degree;
  g.dx = std::round(width / static_cast<double>(nx > 1 ? nx - 1 : 1));
  g.dy = std::round(height / static_cast<double>(ny > 1 ? ny - 1 : 1));
  g.proj = wrf_lcc_proj_string(g.cen_lat, g.cen_lon);
  g.x.resize(nx);
  g.y.resize(ny);
  for (std::size_t i = 0; i < nx; ++i) g.x[i] = g.x_at(static_cast<double>(i));
  for (std::size_t j = 0; j < ny; ++j) g.y[j] = g.y_at(static_cast<double>(j));
  const geo::GridProjection projection(inverse_pipeline(g.proj));
  place(projection, g, nx, ny, 0.0, 0.0, g.lon, g.lat);
  place(projection, g, nx + 1, ny, -0.5, 0.0, g.lon_u, g.lat_u);
  place(projection, g, nx, ny + 1, 0.0, -0.5, g.lon_v, g.lat_v);
  return g;
}

std::pair<double, double> wrf_rotation(const WrfGrid& grid, double lon) {
  const double diff = std::remainder(lon - grid.cen_lon, 360.0);
  const double alpha = diff * cone_factor() * kRadPerDeg;
  return {std::cos(alpha), std::sin(alpha)};
}

}  // namespace strielad::synthetic
