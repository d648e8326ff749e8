// SPDX-License-Identifier: Apache-2.0
// Writes one GRIB2 file of the sample dataset: one message per (step, variable, level),
// on the sample's regular longitude/latitude grid (regular_ll, south to north, west to
// east: the NetCDF file's sample order), levels at their height above sea level
// (heightAboveSea, millimetre precision) or numbered as model levels (hybrid, 1 = top),
// reference time 2013-04-26 12:00 UTC with each step as forecast time in hours or
// minutes. Values are packed grid_simple with `bits` bits or as IEEE float32 (bits 0);
// NaN and kSampleFillValue samples are left out through a bitmap. The file is built under
// temporary_sibling(path) and renamed onto `path` by commit() only. Every ecCodes call
// holds ingest::eccodes_mutex().
#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <span>
#include <string_view>
#include <vector>

#include "synthetic/sample_grid.h"
#include "synthetic/sample_spec.h"
#include "synthetic/sample_variables.h"

namespace strielad::synthetic {

// "height" (heightAboveSea) or "model" (hybrid). Throws kInvalidArgument quoting the text.
GribLevelKind parse_grib_level_kind(std::string_view text);

// The GRIB2 parameter of a sample variable (discipline 0) and ecCodes' shortName for it:
// clw clwc, cli ciwc, qr crwc, ta t, pres pres, ua u, va v, wa wz (geometric vertical
// velocity; ecCodes' w is the pressure vertical velocity).
struct GribParameter {
  long discipline = 0, category = 0, number = 0;
  std::string_view short_name;
};
GribParameter grib_parameter(SampleVariable variable) noexcept;

// Throws kInvalidArgument when the grid's longitudes or latitudes are not evenly spaced
// (beyond 1e-9 degrees), an axis has fewer than 2 points, or its first or last point is
// not a whole number of micro-degrees (GRIB 2's unit), naming the axis.
void check_grib_regular_grid(const SampleGrid& grid);

struct GribSampleLayout {
  std::vector<SampleVariable> variables;  // in this order within each step
  std::vector<double> times;              // seconds since kSampleTimeUnits, per step
  int bits = 16;                          // grid_simple bits per value; 0: IEEE float32
  GribLevelKind levels = GribLevelKind::kHeightAboveSea;
};

class GribSampleFileWriter {
 public:
  // Checks the grid (check_grib_regular_grid), bits (0..32) and times (whole minutes,
  // not negative): kInvalidArgument; creates the temporary file (kIo naming it).
  GribSampleFileWriter(std::filesystem::path path, const SampleGrid& grid,
                       GribSampleLayout layout);
  // Without commit(): removes the temporary file.
  ~GribSampleFileWriter();
  GribSampleFileWriter(const GribSampleFileWriter&) = delete;
  GribSampleFileWriter& operator=(const GribSampleFileWriter&) = delete;

  // Appends the message of level k (0 = top) of variables[variable_index] at time index t
  // of this file; `level` holds lon fastest, then lat, south to north.
  void write_level(std::size_t variable_index, std::size_t t, std::size_t k,
                   std::span<const float> level);

  // Closes, fsyncs and renames the file onto its final path; returns its size in bytes.
  std::uint64_t commit();

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_, temp_path_;
  const SampleGrid& grid_;
  GribSampleLayout layout_;
  std::ofstream out_;
  std::vector<double> values_;
  bool committed_ = false;
};

}  // namespace strielad::synthetic
