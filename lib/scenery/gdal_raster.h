// SPDX-License-Identifier: Apache-2.0
// What the GDAL readers (DEM, drape image) share: an open raster dataset, its
// geotransform (pixel/line to the raster's CRS) and the transformation between that CRS
// and WGS84 longitude/latitude (degrees, longitude first). GDAL's C API only; GDAL's own
// error printing is silenced and its message carried in our errors instead.
#pragma once

#include <array>
#include <filesystem>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "geo/lon_lat.h"

namespace strielad::geo {

class GdalRaster {
 public:
  // \error kNotFound: no such file; kInvalidInput: not a raster GDAL reads, or no
  // geotransform ("no georeferencing"); kUnsupported: a CRS GDAL cannot transform to
  // WGS84. `what` names the role in messages ("DEM", "drape image").
  GdalRaster(const std::filesystem::path& path, const std::string& what);
  ~GdalRaster();
  GdalRaster(const GdalRaster&) = delete;
  GdalRaster& operator=(const GdalRaster&) = delete;

  std::size_t width() const { return width_; }
  std::size_t height() const { return height_; }
  int bands() const { return bands_; }
  const std::string& driver() const { return driver_; }
  const std::string& crs_name() const { return crs_name_; }
  const std::filesystem::path& path() const { return path_; }

  // Pixel (col, row) positions, sample centres at integer + 0.5 in GDAL's convention
  // shifted so that (0, 0) is the first sample's centre, to lon/lat.
  void to_lonlat(std::span<const double> cols, std::span<const double> rows,
                 std::span<LonLat> out) const;
  // Lon/lat to fractional pixel positions (first sample's centre at 0, 0); NaN where the
  // transformation fails.
  void to_pixel(std::span<const LonLat> lonlat, std::span<double> cols,
                std::span<double> rows) const;

  // Reads band `band` (1-based) samples (col0 + i * stride, row0 + j * stride), i < cols,
  // j < rows, as float (GDAL may take them from an overview when stride > 1). NaN where
  // the band's nodata value is. \error kIo naming the file.
  std::vector<float> read_band(int band, std::size_t col0, std::size_t row0, std::size_t cols,
                               std::size_t rows, std::size_t stride) const;

  // Band scale/offset/unit type, nodata.
  double band_scale(int band) const;
  double band_offset(int band) const;
  std::string band_unit(int band) const;

 private:
  std::filesystem::path path_;
  void* dataset_ = nullptr;            // GDALDatasetH
  void* to_wgs84_ = nullptr;           // OGRCoordinateTransformationH (null: identity)
  void* from_wgs84_ = nullptr;
  std::array<double, 6> transform_{};  // geotransform
  std::array<double, 6> inverse_{};
  std::size_t width_ = 0, height_ = 0;
  int bands_ = 0;
  std::string driver_, crs_name_;
  mutable std::mutex mutex_;
};

}  // namespace strielad::geo
