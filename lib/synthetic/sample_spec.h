// SPDX-License-Identifier: Apache-2.0
// What the sample generator is asked to write (SampleSpec) and what it wrote
// (SampleResult), plus the validation every entry point runs first.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "grid/axis.h"
#include "synthetic/sample_variables.h"

namespace strielad::synthetic {

// The size of the SciVis 2017 ICON-LEM grid regridded to lon/lat: x = lon, y = lat, z.
inline constexpr Dims3 kFullSampleDims{1429, 1556, 150};
// More steps than this is taken for a mistake (a day at 1 s steps is 86,400).
inline constexpr std::size_t kMaxSampleSteps = 1'000'000;

enum class SampleFormat { kNetcdf, kGrib2 };
// GRIB levels: heightAboveSea (the heights in m) or hybrid (numbered 1 = top, as ICON).
enum class GribLevelKind { kHeightAboveSea, kModelLevel };

// "netcdf" or "grib2" (strielad-sample --format). Throws kInvalidArgument quoting the text.
SampleFormat parse_sample_format(std::string_view text);

struct SampleSpec {
  Dims3 dims = kFullSampleDims;
  std::size_t steps = 4;
  std::uint64_t seed = 1;
  std::vector<std::string> variables = all_sample_variable_names();
  bool file_per_step = true;     // sample_t000.nc, sample_t001.nc, ... or one sample.nc
  double step_seconds = 300;     // time between steps
  int deflate = 0;               // 0 (none) .. 9, with the shuffle filter when > 0
  SampleFormat format = SampleFormat::kNetcdf;  // kGrib2: synthetic/grib_sample_writer.h
  int grib_bits = 16;            // GRIB: bits per value (grid_simple); 0: IEEE float32
  GribLevelKind grib_levels = GribLevelKind::kHeightAboveSea;
};

struct SampleFile {
  std::filesystem::path path;
  std::uint64_t bytes = 0;
};

struct SampleResult {
  std::vector<SampleFile> files;  // in time order
  std::uint64_t bytes = 0;        // sum over files
};

// Checks every field and resolves the variable names, in the order given. Throws
// kInvalidArgument naming the offending field (zero dims, steps outside
// 1..kMaxSampleSteps, unknown or
// duplicate variable, deflate outside 0..9, non-positive step_seconds, a level too
// large for one HDF5 chunk; with GRIB: deflate, bits outside 0..32, steps not in whole
// minutes).
std::vector<SampleVariable> validate_sample_spec(const SampleSpec& spec);

// File names the spec produces (sample_t000.nc or .grib2 ...), relative to the output directory.
std::vector<std::string> sample_file_names(const SampleSpec& spec);

}  // namespace strielad::synthetic
