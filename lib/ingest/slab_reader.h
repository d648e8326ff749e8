// SPDX-License-Identifier: Apache-2.0
// SlabReader: z-slabs of one variable and time step of the catalogued input files.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "ingest/input_catalog.h"

namespace strielad::ingest {

// Reads z-slabs of one variable and time step: samples [z0, z1) x all lat x all lon,
// x fastest, unpacked (scale_factor/add_offset), with _FillValue, missing_value and
// samples outside valid_min/valid_max (or valid_range) set to NaN. NaN/Inf in the data
// throws kInvalidInput naming file, variable, step and sample index unless
// ScanOptions::nan_as_fill. Safe to call from several threads (netCDF calls are
// serialized; direct reads run in parallel); keeps files open between calls.
//
// With ScanOptions::direct_input, planes of a netCDF-4 variable that HDF5 stores as raw
// little-endian samples (no filters; contiguous, or chunks of whole planes) are read
// with O_DIRECT in pieces and converted from there: an input that is read once costs
// no page-cache work (on a 2-core VM, reading 5.3 GB buffered took 15 s of system
// time against 0.4 s direct). Anything else, and file systems without O_DIRECT, read
// through netCDF. The result is the same either way.
class SlabReader {
 public:
  SlabReader(const InputCatalog& catalog, const ScanOptions& options);
  ~SlabReader();
  SlabReader(const SlabReader&) = delete;
  SlabReader& operator=(const SlabReader&) = delete;

  void read(std::size_t variable, std::size_t step, std::size_t z0, std::size_t z1,
            std::span<float> out);
  void read(std::size_t variable, std::size_t step, std::size_t z0, std::size_t z1,
            std::span<double> out);

  // The catalog's vertical geometry at `step` for levels [z0, z1): height above mean sea
  // level in m, or pressure in Pa, per sample, x fastest (the order of read()). Half-
  // level sources are averaged onto the variables' levels, staggered ones destaggered.
  // \error kInvalidInput naming the source variable, the sample (i, j, k) and the step
  // for a missing or non-finite value; kInvalidArgument without a vertical geometry.
  void read_vertical_geometry(std::size_t step, std::size_t z0, std::size_t z1,
                              std::span<double> out);
  // The catalog it reads (as the files hold it: without a repeated first meridian).
  const InputCatalog& catalog() const;

  // The catalog's surface height, y.size() * x.size() values in m, x fastest.
  // \error as read_vertical_geometry; kInvalidArgument without a surface.
  void read_surface(std::span<double> out);

  // Direct reads go in pieces of at most this many bytes: the per-thread aligned buffer
  // stays small, and each piece is converted while it is still in cache.
  static constexpr std::size_t kDirectPieceBytes = std::size_t{16} << 20;

  // Input bytes read so far with O_DIRECT (the rest went through netCDF).
  std::uint64_t direct_bytes() const;

 private:
  template <typename T>
  void read_any(std::size_t variable, std::size_t step, std::size_t z0, std::size_t z1,
                std::span<T> out);

  struct Impl;
  Impl* impl_;
  bool repeat_first_column_ = false;  // the catalog repeats the first meridian at the end
};

}  // namespace strielad::ingest
