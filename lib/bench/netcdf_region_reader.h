// SPDX-License-Identifier: Apache-2.0
// The NetCDF side of the brick-read comparison: reads one box of a variable (time, z, y, x)
// from a chunked NetCDF-4 file with nc_get_vara_float, the file kept open between reads
// (as a store keeps its index) and the HDF5 chunk cache sized by the caller (0: every read
// goes to the file, so a cold read really reads and inflates the chunks).
#pragma once

#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "octree/octree_layout.h"

namespace strielad::bench {

class NetcdfRegionReader {
 public:
  // Opens the file and looks up the variables. Throws kIo / kNotFound naming the file.
  NetcdfRegionReader(const std::filesystem::path& path, const std::vector<std::string>& variables,
                     std::size_t chunk_cache_bytes = 0);
  ~NetcdfRegionReader();
  NetcdfRegionReader(const NetcdfRegionReader&) = delete;
  NetcdfRegionReader& operator=(const NetcdfRegionReader&) = delete;

  // Reads the inclusive level-0 box (x, y, z) of variable `index` at time `step` into
  // `out` (resized; x fastest). Throws kIo naming file and variable.
  void read_box(std::size_t index, std::size_t step, const IndexBox& box, std::vector<float>& out);

  // The chunk shape of a variable (z, y, x), or empty when contiguous.
  std::vector<std::size_t> chunking(std::size_t index) const;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  int ncid_ = -1;
  std::vector<int> varids_;
  std::vector<std::string> names_;
};

}  // namespace strielad::bench
