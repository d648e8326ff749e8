// SPDX-License-Identifier: Apache-2.0
#include "synthetic/sample_writer.h"

#include <fcntl.h>
#include <netcdf.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <mutex>
#include <string>
#include <string_view>

#include "core/error.h"
#include "core/file_io.h"
#include "ingest/netcdf_call.h"

namespace strielad::synthetic {
namespace {

using ingest::nc_check;
using ingest::netcdf_mutex;

// Callers hold netcdf_mutex().
void put_text(int ncid, int varid, const char* name, std::string_view value,
              const std::string& context) {
  nc_check(nc_put_att_text(ncid, varid, name, value.size(), value.data()),
           fmt::format("{}: attribute {}", context, name));
}

int define_coordinate(int ncid, const char* name, int dimid, const std::string& context) {
  int varid = -1;
  nc_check(nc_def_var(ncid, name, NC_DOUBLE, 1, &dimid, &varid),
           fmt::format("{}: define coordinate {}", context, name));
  return varid;
}

// The four dimensions (time unlimited) and their CF coordinate variables.
struct Coordinates {
  int dim_time = -1, dim_height = -1, dim_lat = -1, dim_lon = -1;
  int v_time = -1, v_height = -1, v_lat = -1, v_lon = -1;
};

// Callers hold netcdf_mutex().
Coordinates define_coordinates(int ncid, const Dims3& dims, const std::string& ctx) {
  Coordinates c;
  nc_check(nc_def_dim(ncid, "time", NC_UNLIMITED, &c.dim_time), ctx + ": define time");
  nc_check(nc_def_dim(ncid, "height", dims.z, &c.dim_height), ctx + ": define height");
  nc_check(nc_def_dim(ncid, "lat", dims.y, &c.dim_lat), ctx + ": define lat");
  nc_check(nc_def_dim(ncid, "lon", dims.x, &c.dim_lon), ctx + ": define lon");

  c.v_time = define_coordinate(ncid, "time", c.dim_time, ctx);
  put_text(ncid, c.v_time, "standard_name", "time", ctx);
  put_text(ncid, c.v_time, "long_name", "time", ctx);
  put_text(ncid, c.v_time, "units", kSampleTimeUnits, ctx);
  put_text(ncid, c.v_time, "calendar", "proleptic_gregorian", ctx);
  put_text(ncid, c.v_time, "axis", "T", ctx);

  c.v_height = define_coordinate(ncid, "height", c.dim_height, ctx);
  put_text(ncid, c.v_height, "standard_name", "height", ctx);
  put_text(ncid, c.v_height, "long_name", "height above ground of full levels", ctx);
  put_text(ncid, c.v_height, "units", "m", ctx);
  put_text(ncid, c.v_height, "positive", "up", ctx);
  put_text(ncid, c.v_height, "axis", "Z", ctx);

  c.v_lat = define_coordinate(ncid, "lat", c.dim_lat, ctx);
  put_text(ncid, c.v_lat, "standard_name", "latitude", ctx);
  put_text(ncid, c.v_lat, "long_name", "latitude", ctx);
  put_text(ncid, c.v_lat, "units", "degrees_north", ctx);
  put_text(ncid, c.v_lat, "axis", "Y", ctx);

  c.v_lon = define_coordinate(ncid, "lon", c.dim_lon, ctx);
  put_text(ncid, c.v_lon, "standard_name", "longitude", ctx);
  put_text(ncid, c.v_lon, "long_name", "longitude", ctx);
  put_text(ncid, c.v_lon, "units", "degrees_east", ctx);
  put_text(ncid, c.v_lon, "axis", "X", ctx);
  return c;
}

// One (time, height, lat, lon) float variable per layout variable, chunked by level;
// their ids in layout order. Callers hold netcdf_mutex().
std::vector<int> define_variables(int ncid, const Coordinates& c, const Dims3& dims,
                                  const SampleFileLayout& layout, const std::string& ctx) {
  const int var_dims[4] = {c.dim_time, c.dim_height, c.dim_lat, c.dim_lon};
  const std::size_t chunk[4] = {1, 1, dims.y, dims.x};
  std::vector<int> varids;
  for (const SampleVariable v : layout.variables) {
    const SampleVariableInfo& info = sample_variable_info(v);
    const std::string name(info.name);
    const std::string vctx = fmt::format("{}: variable {}", ctx, name);
    int varid = -1;
    nc_check(nc_def_var(ncid, name.c_str(), NC_FLOAT, 4, var_dims, &varid), vctx + ": define");
    nc_check(nc_def_var_chunking(ncid, varid, NC_CHUNKED, chunk), vctx + ": chunking");
    if (layout.deflate > 0) {
      nc_check(nc_def_var_deflate(ncid, varid, 1, 1, layout.deflate), vctx + ": deflate");
    }
    nc_check(nc_put_att_float(ncid, varid, "_FillValue", NC_FLOAT, 1, &kSampleFillValue),
             vctx + ": _FillValue");
    put_text(ncid, varid, "units", info.units, vctx);
    put_text(ncid, varid, "long_name", info.long_name, vctx);
    if (!info.standard_name.empty()) {
      put_text(ncid, varid, "standard_name", info.standard_name, vctx);
    }
    varids.push_back(varid);
  }
  return varids;
}

// Callers hold netcdf_mutex().
void put_global_attributes(int ncid, unsigned long long seed, const std::string& ctx) {
  put_text(ncid, NC_GLOBAL, "Conventions", "CF-1.8", ctx);
  put_text(ncid, NC_GLOBAL, "title",
           "STRIELAD synthetic sample of ICON-LEM-like output over Germany", ctx);
  put_text(ncid, NC_GLOBAL, "source", "strielad-sample", ctx);
  put_text(ncid, NC_GLOBAL, "comment",
           "Deterministic synthetic fields (standard atmosphere, jet, cyclone, fractal "
           "clouds along frontal bands); not model output.",
           ctx);
  nc_check(nc_put_att_ulonglong(ncid, NC_GLOBAL, "seed", NC_UINT64, 1, &seed),
           ctx + ": attribute seed");
}

}  // namespace

void fsync_path(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0 || ::fsync(fd) != 0) {
    const int err = errno;
    if (fd >= 0) ::close(fd);
    throw make_error(ErrorCode::kIo, "{}: cannot fsync: {}", path.string(), std::strerror(err));
  }
  ::close(fd);
}

std::uint64_t publish_sample_file(const std::filesystem::path& temp_path,
                                  const std::filesystem::path& path) {
  fsync_path(temp_path);
  std::error_code ec;
  std::filesystem::rename(temp_path, path, ec);
  if (ec) {
    throw make_error(ErrorCode::kIo, "{}: cannot rename {} onto it: {}", path.string(),
                     temp_path.string(), ec.message());
  }
  fsync_directory(path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path());
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw make_error(ErrorCode::kIo, "{}: cannot stat: {}", path.string(), ec.message());
  return size;
}

SampleFileWriter::SampleFileWriter(std::filesystem::path path, const SampleGrid& grid,
                                   SampleFileLayout layout)
    : path_(std::move(path)),
      temp_path_(temporary_sibling(path_)),
      dims_(grid.dims),
      time_count_(layout.times.size()) {
  const std::string ctx = path_.string();
  std::lock_guard lock(netcdf_mutex());
  nc_check(nc_create(temp_path_.c_str(), NC_NETCDF4 | NC_CLOBBER, &ncid_),
           fmt::format("{}: cannot create {}", ctx, temp_path_.string()));
  try {
    int old_mode = 0;
    nc_check(nc_set_fill(ncid_, NC_NOFILL, &old_mode), ctx + ": set fill mode");

    const Coordinates c = define_coordinates(ncid_, dims_, ctx);
    varids_ = define_variables(ncid_, c, dims_, layout, ctx);
    put_global_attributes(ncid_, layout.seed, ctx);
    nc_check(nc_enddef(ncid_), ctx + ": end define mode");

    nc_check(nc_put_var_double(ncid_, c.v_height, grid.height.data()), ctx + ": write height");
    nc_check(nc_put_var_double(ncid_, c.v_lat, grid.lat.data()), ctx + ": write lat");
    nc_check(nc_put_var_double(ncid_, c.v_lon, grid.lon.data()), ctx + ": write lon");
    const std::size_t t_start = 0, t_count = layout.times.size();
    nc_check(nc_put_vara_double(ncid_, c.v_time, &t_start, &t_count, layout.times.data()),
             ctx + ": write time");
  } catch (...) {
    nc_close(ncid_);
    ncid_ = -1;
    std::error_code ignored;
    std::filesystem::remove(temp_path_, ignored);
    throw;
  }
}

SampleFileWriter::~SampleFileWriter() {
  close_quietly();
  if (!committed_) {
    std::error_code ignored;
    std::filesystem::remove(temp_path_, ignored);
  }
}

void SampleFileWriter::close_quietly() noexcept {
  if (ncid_ < 0) return;
  std::lock_guard lock(netcdf_mutex());
  nc_close(ncid_);
  ncid_ = -1;
}

void SampleFileWriter::write_level(std::size_t variable_index, std::size_t t, std::size_t k,
                                   std::span<const float> level) {
  if (ncid_ < 0 || variable_index >= varids_.size() || t >= time_count_ || k >= dims_.z ||
      level.size() != dims_.x * dims_.y) {
    throw make_error(ErrorCode::kInternal,
                     "{}: bad level write (variable {}, time {}, level {}, {} floats)",
                     path_.string(), variable_index, t, k, level.size());
  }
  const std::size_t start[4] = {t, k, 0, 0};
  const std::size_t count[4] = {1, 1, dims_.y, dims_.x};
  std::lock_guard lock(netcdf_mutex());
  nc_check(nc_put_vara_float(ncid_, varids_[variable_index], start, count, level.data()),
           fmt::format("{}: write level {} of time {}", path_.string(), k, t));
}

std::uint64_t SampleFileWriter::commit() {
  if (ncid_ < 0 || committed_) {
    throw make_error(ErrorCode::kInternal, "{}: commit of a closed sample file", path_.string());
  }
  {
    std::lock_guard lock(netcdf_mutex());
    const int status = nc_close(ncid_);
    ncid_ = -1;
    nc_check(status, fmt::format("{}: close", temp_path_.string()));
  }
  const std::uint64_t size = publish_sample_file(temp_path_, path_);
  committed_ = true;
  return size;
}

}  // namespace strielad::synthetic
