// SPDX-License-Identifier: Apache-2.0
#include "support/small_dataset.h"

#include <cmath>

#include "support/netcdf_fixture.h"

namespace strielad::testing {
namespace {

constexpr double kFill = -999.0;
constexpr double kPackedFill = -32767.0;

}  // namespace

double small_cloud_value(std::size_t x, std::size_t y, std::size_t z, std::size_t step) {
  if (x >= 3 && x <= 6 && y >= 2 && y <= 5) return std::nan("");  // a block of holes
  const double blob = std::sin(0.7 * double(x + 2 * step)) * std::cos(0.5 * double(y)) *
                      std::sin(0.9 * double(z) + 0.3);
  const double v = blob - 0.45;
  return v > 0 ? static_cast<float>(v * 1e-3) : 0.0;
}

SmallDataset write_small_dataset(const std::filesystem::path& dir, std::size_t nx, std::size_t ny,
                                 std::size_t nz, std::size_t steps) {
  SmallDataset d;
  d.nx = nx;
  d.ny = ny;
  d.nz = nz;
  d.steps = steps;
  std::vector<double> lon(nx), lat(ny), lev(nz);
  for (std::size_t i = 0; i < nx; ++i) lon[i] = 5.0 + 0.1 * double(i) + 0.002 * double(i * i);
  for (std::size_t j = 0; j < ny; ++j) lat[j] = 55.0 - 0.25 * double(j);
  for (std::size_t k = 0; k < nz; ++k) lev[k] = 1000.0 - 600.0 * std::pow(double(k) / double(nz), 1.3);
  for (std::size_t t = 0; t < steps; ++t) {
    SimpleGrid grid;
    grid.lon = lon;
    grid.lat = lat;
    grid.lev = lev;
    grid.time = {300.0 * double(t)};
    grid.time_units = "seconds since 2013-04-26 00:00:00";
    std::vector<double> cloud, temp, packed;
    for (std::size_t k = 0; k < nz; ++k)
      for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i) {
          const double c = small_cloud_value(i, j, k, t);
          cloud.push_back(std::isnan(c) ? kFill : c);
          temp.push_back(290.0 - 4.5 * double(k) + 0.01 * double(i) - 0.02 * double(j) +
                         0.125 * double(t) + 1e-9 * double(i * j));
          packed.push_back((i + j + k) % 17 == 0 ? kPackedFill
                                                 : double((int(i * 37 + j * 11 + k * 5 + t) % 2000) - 1000));
        }
    const auto path = dir / ("small_t" + std::to_string(t) + ".nc");
    NetcdfFixture(NC_NETCDF4)
        .grid(grid)
        .variable("cloud", NC_FLOAT, grid.dims(), cloud,
                  {NcAttr::number("_FillValue", NC_FLOAT, {kFill}),
                   NcAttr::text_value("units", "kg kg-1"),
                   NcAttr::text_value("long_name", "cloud water")})
        .variable("temp", NC_DOUBLE, grid.dims(), temp, {NcAttr::text_value("units", "K")})
        .variable("packed", NC_SHORT, grid.dims(), packed,
                  {NcAttr::number("_FillValue", NC_SHORT, {kPackedFill}),
                   NcAttr::number("scale_factor", NC_FLOAT, {0.01}),
                   NcAttr::number("add_offset", NC_FLOAT, {250.0}),
                   NcAttr::text_value("units", "K")})
        .write(path);
    d.files.push_back(path);
  }
  return d;
}

build::ConvertOptions small_convert_options(const SmallDataset& data,
                                            const std::filesystem::path& store,
                                            std::uint32_t brick) {
  build::ConvertOptions o;
  o.inputs = data.files;
  o.store = store;
  o.brick = brick;
  o.threads = 2;
  return o;
}

}  // namespace strielad::testing
