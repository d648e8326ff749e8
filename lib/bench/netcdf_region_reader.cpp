// SPDX-License-Identifier: Apache-2.0
#include "bench/netcdf_region_reader.h"

#include <netcdf.h>

#include <mutex>

#include "core/error.h"
#include "ingest/netcdf_call.h"

namespace strielad::bench {

NetcdfRegionReader::NetcdfRegionReader(const std::filesystem::path& path,
                                       const std::vector<std::string>& variables,
                                       std::size_t chunk_cache_bytes)
    : path_(path), names_(variables) {
  std::lock_guard lock(ingest::netcdf_mutex());
  ingest::nc_check(nc_open(path.c_str(), NC_NOWRITE, &ncid_), path.string() + ": open");
  try {
    for (const auto& name : variables) {
      int varid = -1;
      if (nc_inq_varid(ncid_, name.c_str(), &varid) != NC_NOERR) {
        throw make_error(ErrorCode::kNotFound, "{}: no variable '{}'", path.string(), name);
      }
      ingest::nc_check(nc_set_var_chunk_cache(ncid_, varid, chunk_cache_bytes, 1009, 0.75f),
                       path.string() + ": " + name + ": chunk cache");
      varids_.push_back(varid);
    }
  } catch (...) {
    nc_close(ncid_);
    throw;
  }
}

NetcdfRegionReader::~NetcdfRegionReader() {
  std::lock_guard lock(ingest::netcdf_mutex());
  if (ncid_ >= 0) nc_close(ncid_);
}

void NetcdfRegionReader::read_box(std::size_t index, std::size_t step, const IndexBox& box,
                                  std::vector<float>& out) {
  const std::size_t start[4] = {step, box.lo[2], box.lo[1], box.lo[0]};
  const std::size_t count[4] = {1, box.extent(2), box.extent(1), box.extent(0)};
  out.resize(box.count());
  std::lock_guard lock(ingest::netcdf_mutex());
  ingest::nc_check(nc_get_vara_float(ncid_, varids_.at(index), start, count, out.data()),
                   path_.string() + ": " + names_.at(index) + ": nc_get_vara_float");
}

std::vector<std::size_t> NetcdfRegionReader::chunking(std::size_t index) const {
  std::lock_guard lock(ingest::netcdf_mutex());
  int storage = 0;
  std::size_t sizes[NC_MAX_VAR_DIMS] = {};
  ingest::nc_check(nc_inq_var_chunking(ncid_, varids_.at(index), &storage, sizes),
                   path_.string() + ": " + names_.at(index) + ": chunking");
  if (storage != NC_CHUNKED) return {};
  int ndims = 0;
  ingest::nc_check(nc_inq_varndims(ncid_, varids_.at(index), &ndims), path_.string());
  std::vector<std::size_t> out;
  for (int d = ndims - 3; d < ndims; ++d) out.push_back(sizes[d]);
  return out;
}

}  // namespace strielad::bench
