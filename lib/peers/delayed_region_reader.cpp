// SPDX-License-Identifier: Apache-2.0
#include "peers/delayed_region_reader.h"

#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include "core/error.h"

namespace strielad::peers {

struct DelayedRegionReader::Grids {
  std::vector<std::unique_ptr<openvdb::io::File>> files;  // kept open: the grids map them
  std::vector<openvdb::FloatGrid::Ptr> grids;
};

DelayedRegionReader::DelayedRegionReader(const std::vector<std::filesystem::path>& files,
                                         const std::vector<std::string>& grids)
    : grids_(std::make_unique<Grids>()) {
  openvdb::initialize();
  if (files.size() != grids.size()) {
    throw make_error(ErrorCode::kInvalidArgument, "{} .vdb files for {} grid names", files.size(),
                     grids.size());
  }
  for (std::size_t i = 0; i < files.size(); ++i) {
    if (!std::filesystem::is_regular_file(files[i])) {
      throw make_error(ErrorCode::kNotFound, "{}: no such .vdb file", files[i].string());
    }
    try {
      auto file = std::make_unique<openvdb::io::File>(files[i].string());
      file->setCopyMaxBytes(0);  // map the file; never copy it to a temporary first
      file->open(/*delayLoad=*/true);
      if (!file->hasGrid(grids[i])) {
        throw make_error(ErrorCode::kNotFound, "{}: no grid '{}'", files[i].string(), grids[i]);
      }
      auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file->readGrid(grids[i]));
      if (!grid) {
        throw make_error(ErrorCode::kInvalidInput, "{}: grid '{}' is not a FloatGrid",
                         files[i].string(), grids[i]);
      }
      grids_->grids.push_back(std::move(grid));
      grids_->files.push_back(std::move(file));
    } catch (const openvdb::Exception& e) {
      throw make_error(ErrorCode::kIo, "{}: OpenVDB cannot read it: {}", files[i].string(), e.what());
    }
  }
}

DelayedRegionReader::~DelayedRegionReader() = default;

void DelayedRegionReader::read_box(std::size_t index, const IndexBox& box, std::vector<float>& out) {
  const auto& grid = *grids_->grids.at(index);
  const std::size_t nx = box.hi[0] - box.lo[0] + 1, ny = box.hi[1] - box.lo[1] + 1,
                    nz = box.hi[2] - box.lo[2] + 1;
  out.resize(nx * ny * nz);
  auto accessor = grid.getConstAccessor();
  std::size_t i = 0;
  for (std::size_t z = box.lo[2]; z <= box.hi[2]; ++z) {
    for (std::size_t y = box.lo[1]; y <= box.hi[1]; ++y) {
      for (std::size_t x = box.lo[0]; x <= box.hi[0]; ++x) {
        out[i++] = accessor.getValue(openvdb::Coord(int(x), int(y), int(z)));
      }
    }
  }
}

std::size_t DelayedRegionReader::unloaded_leaves() const {
  std::size_t n = 0;
  for (const auto& g : grids_->grids) {
    for (auto leaf = g->tree().cbeginLeaf(); leaf; ++leaf) n += leaf->buffer().isOutOfCore();
  }
  return n;
}

}  // namespace strielad::peers
