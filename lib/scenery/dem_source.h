// SPDX-License-Identifier: Apache-2.0
// A digital elevation model as the viewer's terrain reads it: a grid of
// width x height samples, each georeferenced to geographic longitude/latitude (WGS84
// degrees), heights read window by window, never the whole grid at once.
//
// Sources (open_dem):
// - CF-NetCDF: a 2-D variable (leading dimensions of length 1, e.g. time, are allowed)
//   chosen by name, or else the first with standard_name surface_altitude, or named
//   HSURF, z_ifc, topography_c, orog or elevation; georeferenced by 1-D longitude and
//   latitude axes (ascending or descending, any spacing) or by 1-D map axes with a CF
//   grid_mapping (a rotated_latitude_longitude pole as COSMO, CCLM and EURO-CORDEX write
//   it, or any projection geo/cf_grid_mapping.h translates), placed through the
//   mapping's PROJ pipeline (geo/grid_projection.h), the mechanism that places the
//   stores; units m or km.
//   Fill: _FillValue (or netCDF's default fill when none is declared), missing_value,
//   valid_range/valid_min/valid_max; packed values unpacked with scale_factor/add_offset.
// - any raster GDAL reads (GeoTIFF, ...): band 1, georeferenced by its geotransform,
//   its CRS transformed to WGS84 longitude/latitude; nodata -> NaN.
// Sample (col, row) is the value at storage index (row, col): row 0 is the file's first
// row, whatever direction it runs in. Heights are metres; missing samples are NaN.
//
// Thread safety: every member may be called from any thread (calls into netCDF hold
// ingest::netcdf_mutex(); GDAL datasets and coordinate transformations are locked).
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "geo/lon_lat.h"

namespace strielad::geo {

// Samples (col0 + i * stride, row0 + j * stride) for i < cols, j < rows.
struct DemWindow {
  std::size_t col0 = 0, row0 = 0;
  std::size_t cols = 0, rows = 0;
  std::size_t stride = 1;  // >= 1
};

class DemSource {
 public:
  virtual ~DemSource() = default;

  virtual std::size_t width() const = 0;   // samples per row (columns)
  virtual std::size_t height() const = 0;  // rows

  // Geographic lon/lat of (possibly fractional) sample positions, n at a time
  // (cols.size() == rows.size() == out.size()); positions outside the grid extrapolate;
  // NaN where a projection has no geographic position.
  virtual void georeference(std::span<const double> cols, std::span<const double> rows,
                            std::span<LonLat> out) const = 0;
  LonLat georeference(double col, double row) const;

  // Heights in metres, row-major (window.rows rows of window.cols), NaN where missing.
  // \error kInvalidArgument for a window outside the grid or a zero stride; kIo / kInvalidInput
  // naming the file and variable when the read fails.
  virtual std::vector<float> read(const DemWindow& window) const = 0;

  // "FILE:VARIABLE" or "FILE (GDAL driver GTiff)", for messages and the panel.
  virtual std::string describe() const = 0;
  // How samples are placed: "longitude/latitude axes", "grid mapping 'rotated_pole'
  // (rotated_latitude_longitude) through PROJ: +proj=...", the CRS name...
  virtual std::string georeferencing() const = 0;
};

// Opens `path` as NetCDF when netCDF-C can read it (variable `variable`, or found as
// above when empty), else through GDAL.
// \error kNotFound: no such file, or no such variable (naming the file and variable);
// kInvalidInput: the variable is not 2-D, has no georeferencing, or the file is neither
// NetCDF nor a raster GDAL reads; kUnsupported: a grid_mapping or CRS this reader does not
// transform (naming it).
std::unique_ptr<DemSource> open_dem(const std::filesystem::path& path,
                                    const std::string& variable = "");

// The two readers, for callers that know the format.
std::unique_ptr<DemSource> open_netcdf_dem(const std::filesystem::path& path,
                                           const std::string& variable);
std::unique_ptr<DemSource> open_gdal_dem(const std::filesystem::path& path);

// Checks a window against a width x height grid. \error kInvalidArgument naming `what`.
void check_dem_window(const DemWindow& window, std::size_t width, std::size_t height,
                      const std::string& what);

}  // namespace strielad::geo
