// SPDX-License-Identifier: Apache-2.0
// A georeferenced image draped over the terrain (any raster GDAL reads): RGB (bands
// 1-3) or greyscale (band 1), 8-bit values (others are clamped to 0-255). Read per
// terrain tile, never whole: the part of the image under a tile's vertices, at most
// max_size x max_size texels (GDAL takes coarser samples, from overviews where the file
// has them), with each vertex's texture coordinate found through the image's own
// georeferencing (its CRS from WGS84 longitude/latitude, then the inverse geotransform).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "geo/lon_lat.h"

namespace strielad::geo {

class GdalRaster;

struct DrapePatch {
  int width = 0, height = 0;        // texels; 0 x 0: the image does not cover the tile
  std::vector<std::uint8_t> rgba;   // rows, first row first (the image's row order)
};

class DrapeImage {
 public:
  // \error as GdalRaster: kNotFound, kInvalidInput (not a raster, no georeferencing),
  // kUnsupported (a CRS without a transformation to WGS84).
  explicit DrapeImage(const std::filesystem::path& path);
  ~DrapeImage();

  // The patch under `lonlat` (a tile's vertices) and each vertex's texture coordinate
  // (u along the patch's columns, v along its rows, texel centres at (i + 0.5) / size);
  // vertices off the image get coordinates outside [0, 1]. Thread-safe.
  DrapePatch read(std::span<const LonLat> lonlat, std::span<float> u, std::span<float> v,
                  int max_size = 256) const;

  std::string describe() const;

 private:
  std::unique_ptr<GdalRaster> raster_;
};

}  // namespace strielad::geo
