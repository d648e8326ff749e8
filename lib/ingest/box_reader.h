// SPDX-License-Identifier: Apache-2.0
// Reads small boxes of one variable at one time step straight from its netCDF file, with
// the CF conversion of ingest::SlabReader (fill and missing values to NaN, unpacking).
// For sampling a few bricks at plan time (build/predictor_choice.h), where reading whole
// planes would cost a good part of a conversion: an unfiltered chunked variable is read
// with HDF5's chunk cache off, so only the box's rows come from disk; a filtered one
// (deflate, shuffle, ...) decompresses every chunk the box touches, once per read.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "ingest/hdf5_plane_layout.h"
#include "ingest/input_catalog.h"
#include "ingest/slab_reader.h"
#include "octree/octree_layout.h"

namespace strielad::build {

class BoxReader {
 public:
  // Opens the file holding (variable, step). Throws like ingest::SlabReader.
  BoxReader(const ingest::InputCatalog& catalog, const ingest::ScanOptions& scan,
            std::size_t variable, std::size_t step);
  ~BoxReader();
  BoxReader(const BoxReader&) = delete;
  BoxReader& operator=(const BoxReader&) = delete;

  // Whether the variable's storage is filtered: every read decompresses whole chunks.
  bool filtered() const;

  // Asks the kernel to start reading the box's bytes into the page cache, all at once
  // (posix_fadvise WILLNEED), so that the reads that follow find them there instead of
  // waiting on the disk row by row. Only where the planes are raw bytes whose file offsets
  // HDF5 gives (ingest/hdf5_plane_layout.h); elsewhere it does nothing. Measured on a cold
  // paper step: the predictor trial's reads take 0.2 s instead of 1 s (BENCHMARKS.md).
  void prefetch(const IndexBox& box);
  // The file ranges prefetch() asks for: per plane of the box, from its first row's first
  // sample to its last row's last sample (whole rows in between). Empty where it does
  // nothing.
  std::vector<ingest::FileRange> prefetch_ranges(const IndexBox& box) const;

  // Level-0 samples box.lo..box.hi (inclusive, x fastest) into `out` (box.count()).
  // NaN/Inf that the data does not declare missing become NaN without an error: the
  // conversion itself reports them.
  void read(const IndexBox& box, std::span<float> out);
  void read(const IndexBox& box, std::span<double> out);

 private:
  template <typename Out>
  void read_any(const IndexBox& box, std::span<Out> out);

  struct Impl;
  static void open_variable(Impl& impl, Dims3 dims);  // caller holds netcdf_mutex()
  std::unique_ptr<Impl> impl_;
};

}  // namespace strielad::build
