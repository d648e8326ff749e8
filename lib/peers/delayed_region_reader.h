// SPDX-License-Identifier: Apache-2.0
// The OpenVDB side of the brick-read comparison (strielad-bench io): level-0 .vdb files
// (one per variable, as write_level_vdb writes them) opened with OpenVDB's delayed
// loading: io::File::open(true) with copy-max-bytes 0, so the file is memory-mapped and
// not first copied whole; every grid's topology is read once at open (as a store keeps
// its index), and a box is read voxel by voxel through an accessor, which loads the leaf
// buffers it touches from the file on first use. Free of OpenVDB types.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "octree/octree_layout.h"

namespace strielad::peers {

class DelayedRegionReader {
 public:
  // `files[i]` holds a FloatGrid named `grids[i]`. \error kNotFound naming a file or a
  // grid that is not there; kIo when OpenVDB cannot read a file.
  DelayedRegionReader(const std::vector<std::filesystem::path>& files,
                      const std::vector<std::string>& grids);
  ~DelayedRegionReader();
  DelayedRegionReader(const DelayedRegionReader&) = delete;
  DelayedRegionReader& operator=(const DelayedRegionReader&) = delete;

  // Reads the inclusive level-0 box (x, y, z) of grid `index` into `out` (resized; x
  // fastest); inactive voxels read as the grid's background.
  void read_box(std::size_t index, const IndexBox& box, std::vector<float>& out);

  // Leaf buffers not yet loaded from the file, over every grid (a measure of what the
  // reads so far have touched).
  std::size_t unloaded_leaves() const;

 private:
  struct Grids;
  std::unique_ptr<Grids> grids_;
};

}  // namespace strielad::peers
