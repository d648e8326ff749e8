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

#include "ingest/input_catalog.h"
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

  // Level-0 samples box.lo..box.hi (inclusive, x fastest) into `out` (box.count()).
  // NaN/Inf that the data does not declare missing become NaN without an error: the
  // conversion itself reports them.
  void read(const IndexBox& box, std::span<float> out);
  void read(const IndexBox& box, std::span<double> out);

 private:
  struct Impl;
  static void open_variable(Impl& impl, Dims3 dims);  // caller holds netcdf_mutex()
  std::unique_ptr<Impl> impl_;
};

}  // namespace strielad::build
