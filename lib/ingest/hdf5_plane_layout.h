// SPDX-License-Identifier: Apache-2.0
// Where a netCDF-4 variable's horizontal (lat x lon) planes lie in its HDF5 file, when
// HDF5 keeps them as raw bytes that the converter can read itself: no filters,
// little-endian samples of the variable's own netCDF type, stored contiguously or in
// chunks that each hold whole planes (model output is usually chunked one plane per
// chunk, or not at all). The converter then reads the planes with O_DIRECT instead of
// through netCDF, which saves the page cache's work on inputs read once.
// Every call goes into HDF5: the caller holds netcdf_mutex().
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "grid/axis.h"

namespace strielad::ingest {

struct FileRange {
  std::uint64_t offset = 0;  // bytes from the start of the file
  std::uint64_t bytes = 0;
  friend bool operator==(const FileRange&, const FileRange&) = default;
};

class Hdf5PlaneLayout {
 public:
  // The layout of `variable` ("T" or "grp/T", of netCDF type `nc_type`, with dims
  // [time,] z, y, x) in the netCDF-4 file `path`; nullptr with the reason in `why_not`
  // when its planes are not raw bytes there (filters, big-endian, chunks smaller than a
  // plane, a name netCDF stores under another HDF5 name...).
  static std::unique_ptr<Hdf5PlaneLayout> open(const std::string& path,
                                               const std::string& variable, int nc_type,
                                               bool has_time, const Dims3& dims,
                                               std::string* why_not);
  Hdf5PlaneLayout(const Hdf5PlaneLayout&) = delete;
  Hdf5PlaneLayout& operator=(const Hdf5PlaneLayout&) = delete;
  ~Hdf5PlaneLayout();

  // The file byte ranges of planes [z0, z1) of time index `t`, in plane order, adjacent
  // ranges merged. nullopt when a chunk they lie in was never written (its samples are
  // the fill value, which netCDF supplies).
  std::optional<std::vector<FileRange>> planes(std::size_t t, std::size_t z0,
                                               std::size_t z1) const;

 private:
  Hdf5PlaneLayout() = default;

  std::int64_t file_ = -1;     // hid_t
  std::int64_t dataset_ = -1;  // hid_t
  bool has_time_ = false;
  bool chunked_ = false;
  std::uint64_t contiguous_offset_ = 0;
  std::size_t chunk_time_ = 1, chunk_z_ = 1;  // planes per chunk along time and z
  std::size_t nz_ = 0;
  std::uint64_t plane_bytes_ = 0;
};

}  // namespace strielad::ingest
