// SPDX-License-Identifier: Apache-2.0
// A tiny format-5 store written by hand with the convert encoders: a manifest with a grid
// geometry, one float32 variable "ta", its step files, and the geometry's files
// (GEOMETRY for curvilinear coordinates or a surface; geometry.bricks or each step file's
// section V for a vertical field). Every value is an integer, exact in float32, given by
// the functions below, so tests can predict samples and statistics.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "format/geometry_file_format.h"
#include "format/manifest.h"

namespace strielad::testing {

enum class GeometryField { kNone, kInvariant, kVarying };

struct GeometryStoreSpec {
  std::size_t nx = 5, ny = 4, nz = 5, steps = 2;
  std::uint32_t brick = 2;
  bool curvilinear = true;
  bool surface = true;
  GeometryField field = GeometryField::kInvariant;
};

// Writes the store into `dir` (created) and returns its manifest (complete).
format::Manifest write_geometry_store(const std::filesystem::path& dir,
                                      const GeometryStoreSpec& spec = {});

// Sample (x, y, z) of "ta" at `step`.
double geometry_store_value(std::size_t x, std::size_t y, std::size_t z, std::size_t step);
// Sample (x, y, z) of the vertical field (height, m) at `step`: the same at every step
// unless the field varies in time.
double geometry_store_height(const GeometryStoreSpec& spec, std::size_t x, std::size_t y,
                             std::size_t z, std::size_t step);
// The GEOMETRY file's arrays (lon and lat only for a curvilinear grid, surface only with
// one).
format::HorizontalCoordinates geometry_store_coordinates(const GeometryStoreSpec& spec);

}  // namespace strielad::testing
