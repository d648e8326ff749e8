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

}  // namespace strielad::synthetic
