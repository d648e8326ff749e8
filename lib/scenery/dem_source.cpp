// SPDX-License-Identifier: Apache-2.0
#include "scenery/dem_source.h"

#include <array>
#include <fstream>

#include "core/error.h"

namespace strielad::geo {

LonLat DemSource::georeference(double col, double row) const {
  LonLat out;
  georeference(std::span<const double>(&col, 1), std::span<const double>(&row, 1),
               std::span<LonLat>(&out, 1));
  return out;
}

void check_dem_window(const DemWindow& w, std::size_t width, std::size_t height,
                      const std::string& what) {
  if (w.stride == 0 || w.cols == 0 || w.rows == 0 || w.col0 >= width || w.row0 >= height ||
      w.col0 + (w.cols - 1) * w.stride >= width || w.row0 + (w.rows - 1) * w.stride >= height) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "{}: window of {} x {} samples from ({}, {}) with stride {} is outside the "
                     "{} x {} grid",
                     what, w.cols, w.rows, w.col0, w.row0, w.stride, width, height);
  }
}

namespace {

// NetCDF classic ("CDF\1", "CDF\2", "CDF\5") or NetCDF-4/HDF5 ("\x89HDF\r\n\x1a\n").
bool looks_like_netcdf(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<char, 8> magic{};
  if (!in.read(magic.data(), magic.size())) return false;
  if (magic[0] == 'C' && magic[1] == 'D' && magic[2] == 'F' &&
      (magic[3] == 1 || magic[3] == 2 || magic[3] == 5)) {
    return true;
  }
  return magic[0] == '\x89' && magic[1] == 'H' && magic[2] == 'D' && magic[3] == 'F';
}

}  // namespace

std::unique_ptr<DemSource> open_dem(const std::filesystem::path& path, const std::string& variable) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw make_error(ErrorCode::kNotFound, "{}: no such DEM file", path.string());
  }
  if (looks_like_netcdf(path)) return open_netcdf_dem(path, variable);
  if (!variable.empty()) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "{}: --terrain-var {} is for NetCDF files; this file is read through GDAL "
                     "(band 1)",
                     path.string(), variable);
  }
  return open_gdal_dem(path);
}

}  // namespace strielad::geo
