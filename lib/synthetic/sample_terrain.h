// SPDX-License-Identifier: Apache-2.0
// A synthetic DEM under the sample domain, written as CF-NetCDF on a
// rotated-pole grid like the regional models' (the HSURF of COSMO/CCLM: pole at 39.25 N,
// 162 W), so the sample exercises the same reading path as real model output.
// Deterministic from the seed: Alps-like ranges in the south (up to about 3.5 km),
// low mountains across the middle (Black Forest, Harz, Erzgebirge... at roughly their
// places, 0.6-1.2 km), the northern lowlands, and the North Sea and the Baltic in the
// north as _FillValue (sea without data: the terrain's fill rule draws it at height 0).
// HSURF(rlat, rlon) in metres with standard_name surface_altitude, the rotated_pole
// grid_mapping, and 2-D lat/lon auxiliary coordinates.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace strielad::synthetic {

struct SampleTerrainSpec {
  std::size_t samples = 1024;  // along each rotated axis (2 .. 16384)
  std::uint64_t seed = 1;
};

struct SampleTerrainResult {
  std::size_t width = 0, height = 0;
  std::uint64_t bytes = 0;
  float max_height_m = 0;
};

// Writes `path` atomically. \error kInvalidArgument for a size outside 2 .. 16384;
// kIo when the file cannot be written.
SampleTerrainResult write_sample_terrain(const SampleTerrainSpec& spec,
                                         const std::filesystem::path& path);

// The same surface at the points of a regular lon/lat grid (degrees; x fastest, lon.size()
// * lat.size() values, metres above sea level) with the sea at 0 m instead of the fill
// value: the model surface of the model-like samples (model_like_files.h).
std::vector<float> sample_terrain_heights(std::span<const double> lon, std::span<const double> lat,
                                          std::uint64_t seed);

// The same surface at arbitrary points (lon[p], lat[p]) in degrees, e.g. the mass points
// of a projected model grid; kInternal when the spans differ in length.
std::vector<float> sample_terrain_heights_at(std::span<const double> lon,
                                             std::span<const double> lat, std::uint64_t seed);

}  // namespace strielad::synthetic
