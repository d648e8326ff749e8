// SPDX-License-Identifier: Apache-2.0
// Writes one CF-NetCDF-4 file of the sample dataset: var(time, height, lat, lon) float32,
// chunked one level per chunk, optionally deflated with shuffle. The file is built under
// temporary_sibling(path) and renamed onto `path` only by commit(), so an interrupted run
// never leaves a file that looks complete. Every nc_* call holds netcdf_mutex().
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "synthetic/sample_grid.h"
#include "synthetic/sample_variables.h"

namespace strielad::synthetic {

struct SampleFileLayout {
  std::vector<SampleVariable> variables;  // written in this order
  std::vector<double> times;              // seconds since the reference time, per step
  std::uint64_t seed = 0;
  int deflate = 0;
};

inline constexpr float kSampleFillValue = -9.0e33f;
// Noon UTC: the HD(CP)2 LEM day over Germany was a day of daytime convection, and a
// sample lit by the true sun (strielad-view --sun time) should be seen in daylight.
inline constexpr const char* kSampleTimeUnits = "seconds since 2013-04-26 12:00:00";

// Flushes a written file to disk. Throws kIo naming the file.
void fsync_path(const std::filesystem::path& path);

// Publishes a closed temporary file: fsyncs it, renames it onto `path` and fsyncs the
// directory. Returns the file's size in bytes. Throws kIo naming the files.
std::uint64_t publish_sample_file(const std::filesystem::path& temp_path,
                                  const std::filesystem::path& path);

class SampleFileWriter {
 public:
  // Creates the temporary file and defines dimensions, coordinates and variables; writes
  // the coordinate values. Throws kIo naming the file when it cannot be created.
  SampleFileWriter(std::filesystem::path path, const SampleGrid& grid, SampleFileLayout layout);
  // Without commit(): closes and removes the temporary file.
  ~SampleFileWriter();
  SampleFileWriter(const SampleFileWriter&) = delete;
  SampleFileWriter& operator=(const SampleFileWriter&) = delete;

  // Writes level k (0 = top) of variables[variable_index] at time index t of this file.
  void write_level(std::size_t variable_index, std::size_t t, std::size_t k,
                   std::span<const float> level);

  // Closes, fsyncs and renames the file onto its final path; returns its size in bytes.
  std::uint64_t commit();

  const std::filesystem::path& path() const { return path_; }

 private:
  void close_quietly() noexcept;

  std::filesystem::path path_, temp_path_;
  Dims3 dims_;
  std::size_t time_count_ = 0;
  int ncid_ = -1;
  std::vector<int> varids_;
  bool committed_ = false;
};

}  // namespace strielad::synthetic
