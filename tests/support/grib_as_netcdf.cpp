// SPDX-License-Identifier: Apache-2.0
#include "support/grib_as_netcdf.h"

#include <fstream>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/file_io.h"
#include "ingest/grib_catalog.h"
#include "ingest/grib_scan.h"
#include "ingest/input_catalog.h"
#include "support/netcdf_fixture.h"

namespace strielad::testing {
namespace {

std::vector<NcAttr> mapping_attributes(const GridMapping& m, double central_meridian_shift) {
  std::vector<NcAttr> attrs;
  for (const auto& [key, value] : m.attributes.items()) {
    if (value.is_string()) {
      attrs.push_back(NcAttr::text_value(key, value.get<std::string>()));
    } else if (value.is_array()) {
      attrs.push_back(NcAttr::number(key, NC_DOUBLE, value.get<std::vector<double>>()));
    } else {
      double v = value.get<double>();
      if (key == "longitude_of_central_meridian") v += central_meridian_shift;
      attrs.push_back(NcAttr::number(key, NC_DOUBLE, {v}));
    }
  }
  return attrs;
}

}  // namespace

void write_grib_variable_as_netcdf(const std::filesystem::path& grib, const GribAsNetcdf& spec,
                                   const std::filesystem::path& out) {
  ingest::ScanOptions options;
  options.variables = {spec.short_name};
  const ingest::InputCatalog c = ingest::grib_catalog({grib}, options);
  if (!c.grid_mapping || c.repeats_first_column()) {
    throw std::runtime_error(grib.string() + ": not a projected GRIB grid");
  }
  const std::size_t nx = c.x.size(), ny = c.y.size(), nz = c.z.size(), steps = c.time.size();
  const std::size_t keep = nx - spec.drop_columns;
  std::vector<double> data;
  std::vector<float> step(nx * ny * nz);
  for (std::size_t t = 0; t < steps; ++t) {
    const auto& levels = c.locations[0][t].grib_levels;
    ingest::read_grib_levels(grib, levels, nx * ny, grib.string(), step);
    for (std::size_t row = 0; row < ny * nz; ++row) {
      for (std::size_t i = 0; i < keep; ++i) data.push_back(step[row * nx + i]);
    }
  }
  std::vector<double> x(c.x.values.begin(), c.x.values.begin() + static_cast<std::ptrdiff_t>(keep));
  std::vector<double> hours;
  for (const double seconds : c.time.values) hours.push_back(seconds / 3600 + spec.hours_later);

  NetcdfFixture f(NC_NETCDF4);
  std::vector<std::string> dims = {"plev", "y", "x"};
  if (spec.with_time) {
    f.coordinate("time", hours,
                 {NcAttr::text_value("units", "hours since 1970-01-01 00:00:00"),
                  NcAttr::text_value("calendar", "gregorian"),
                  NcAttr::text_value("standard_name", "time"), NcAttr::text_value("axis", "T")},
                 NC_DOUBLE, true);
    dims.insert(dims.begin(), "time");
  } else if (steps != 1) {
    throw std::runtime_error(grib.string() + ": several steps, but no time dimension asked for");
  }
  f.coordinate("plev", c.z.values,
               {NcAttr::text_value("units", c.z.units), NcAttr::text_value("positive", "down"),
                NcAttr::text_value("axis", "Z"),
                NcAttr::text_value("standard_name", "air_pressure")})
      .coordinate("y", c.y.values,
                  {NcAttr::text_value("units", "m"),
                   NcAttr::text_value("standard_name", "projection_y_coordinate"),
                   NcAttr::text_value("axis", "Y")})
      .coordinate("x", x,
                  {NcAttr::text_value("units", "m"),
                   NcAttr::text_value("standard_name", "projection_x_coordinate"),
                   NcAttr::text_value("axis", "X")})
      .variable("lcc", NC_INT, {}, {0},
                mapping_attributes(*c.grid_mapping, spec.central_meridian_shift))
      .variable(spec.name, NC_FLOAT, dims, data,
                {NcAttr::text_value("units", c.variables[0].units),
                 NcAttr::text_value("long_name", c.variables[0].long_name),
                 NcAttr::text_value("grid_mapping", "lcc")})
      .write(out);
}

void copy_grib_variable(const std::filesystem::path& grib, const std::string& short_name,
                        const std::filesystem::path& out) {
  const ingest::GribScan scan = ingest::scan_grib_file(grib);
  const ReadOnlyFile in(grib);
  std::ofstream os(out, std::ios::binary);
  for (const auto& v : scan.variables) {
    if (v.short_name != short_name) continue;
    for (const auto& step : v.messages) {
      for (const auto& m : step) {
        std::vector<std::byte> bytes(static_cast<std::size_t>(m.size));
        in.read_at(m.offset, bytes);
        os.write(reinterpret_cast<const char*>(bytes.data()),
                 static_cast<std::streamsize>(bytes.size()));
      }
    }
    return;
  }
  throw std::runtime_error(grib.string() + ": no GRIB variable " + short_name);
}

}  // namespace strielad::testing
