// SPDX-License-Identifier: Apache-2.0
#include "synthetic/model_netcdf_file.h"

#include <netcdf.h>

#include <mutex>
#include <vector>

#include "core/error.h"
#include "core/file_io.h"
#include "ingest/netcdf_call.h"
#include "synthetic/sample_writer.h"

namespace strielad::synthetic {

using ingest::nc_check;
using ingest::netcdf_mutex;

static_assert(ModelNetcdfFile::kGlobal == NC_GLOBAL);

ModelNetcdfFile::ModelNetcdfFile(std::filesystem::path path, Format format)
    : path_(std::move(path)), temp_path_(temporary_sibling(path_)) {
  std::lock_guard lock(netcdf_mutex());
  const int mode = format == Format::kNetcdf4 ? NC_NETCDF4 : NC_64BIT_OFFSET;
  const int status = nc_create(temp_path_.c_str(), mode | NC_CLOBBER, &ncid_);
  if (status != NC_NOERR) {
    throw make_error(ErrorCode::kIo, "{}: cannot create {}: {}", path_.string(),
                     temp_path_.string(), nc_strerror(status));
  }
  int old_mode = 0;
  const int fill_status = nc_set_fill(ncid_, NC_NOFILL, &old_mode);
  if (fill_status != NC_NOERR) {
    nc_close(ncid_);
    ncid_ = -1;
    std::error_code ignored;
    std::filesystem::remove(temp_path_, ignored);
    nc_check(fill_status, context("set fill mode"));
  }
}

ModelNetcdfFile::~ModelNetcdfFile() {
  if (ncid_ >= 0) {
    std::lock_guard lock(netcdf_mutex());
    nc_close(ncid_);
  }
  if (!committed_) {
    std::error_code ignored;
    std::filesystem::remove(temp_path_, ignored);
  }
}

std::string ModelNetcdfFile::context(std::string_view what) const {
  return fmt::format("{}: {}", path_.string(), what);
}

std::string ModelNetcdfFile::var_context(int varid, std::string_view what) const {
  if (varid == kGlobal) return context(fmt::format("global {}", what));
  const auto index = static_cast<std::size_t>(varid);
  return context(fmt::format("variable {}: {}",
                             index < var_names_.size() ? var_names_[index] : "?", what));
}

int ModelNetcdfFile::dimension(const std::string& name, std::size_t length) {
  std::lock_guard lock(netcdf_mutex());
  int dimid = -1;
  nc_check(nc_def_dim(ncid_, name.c_str(), length == 0 ? NC_UNLIMITED : length, &dimid),
           context("define dimension " + name));
  return dimid;
}

int ModelNetcdfFile::variable(const std::string& name, Type type, std::initializer_list<int> dims) {
  std::lock_guard lock(netcdf_mutex());
  int varid = -1;
  const std::vector<int> ids(dims);
  const nc_type nc = type == Type::kFloat ? NC_FLOAT : type == Type::kDouble ? NC_DOUBLE : NC_CHAR;
  nc_check(nc_def_var(ncid_, name.c_str(), nc,
                      static_cast<int>(ids.size()), ids.data(), &varid),
           context("define variable " + name));
  if (var_names_.size() <= static_cast<std::size_t>(varid)) {
    var_names_.resize(static_cast<std::size_t>(varid) + 1);
  }
  var_names_[static_cast<std::size_t>(varid)] = name;
  return varid;
}

void ModelNetcdfFile::chunk_by_plane(int varid, std::span<const std::size_t> plane_shape,
                                     int deflate) {
  std::lock_guard lock(netcdf_mutex());
  nc_check(nc_def_var_chunking(ncid_, varid, NC_CHUNKED, plane_shape.data()),
           var_context(varid, "chunking"));
  if (deflate > 0) {
    nc_check(nc_def_var_deflate(ncid_, varid, 1, 1, deflate), var_context(varid, "deflate"));
  }
}

void ModelNetcdfFile::text(int varid, const std::string& name, std::string_view value) {
  std::lock_guard lock(netcdf_mutex());
  nc_check(nc_put_att_text(ncid_, varid, name.c_str(), value.size(), value.data()),
           var_context(varid, "attribute " + name));
}

void ModelNetcdfFile::number(int varid, const std::string& name, double value) {
  std::lock_guard lock(netcdf_mutex());
  nc_check(nc_put_att_double(ncid_, varid, name.c_str(), NC_DOUBLE, 1, &value),
           var_context(varid, "attribute " + name));
}

void ModelNetcdfFile::unsigned_number(int varid, const std::string& name, std::uint64_t value) {
  std::lock_guard lock(netcdf_mutex());
  const unsigned long long v = value;
  nc_check(nc_put_att_ulonglong(ncid_, varid, name.c_str(), NC_UINT64, 1, &v),
           var_context(varid, "attribute " + name));
}

void ModelNetcdfFile::float_number(int varid, const std::string& name, float value) {
  std::lock_guard lock(netcdf_mutex());
  nc_check(nc_put_att_float(ncid_, varid, name.c_str(), NC_FLOAT, 1, &value),
           var_context(varid, "attribute " + name));
}

void ModelNetcdfFile::integer(int varid, const std::string& name, int value) {
  std::lock_guard lock(netcdf_mutex());
  nc_check(nc_put_att_int(ncid_, varid, name.c_str(), NC_INT, 1, &value),
           var_context(varid, "attribute " + name));
}

void ModelNetcdfFile::end_define() {
  std::lock_guard lock(netcdf_mutex());
  nc_check(nc_enddef(ncid_), context("end define mode"));
}

void ModelNetcdfFile::put(int varid, std::span<const double> values) {
  std::lock_guard lock(netcdf_mutex());
  nc_check(nc_put_var_double(ncid_, varid, values.data()), var_context(varid, "write"));
}

void ModelNetcdfFile::put(int varid, std::span<const float> values) {
  std::lock_guard lock(netcdf_mutex());
  nc_check(nc_put_var_float(ncid_, varid, values.data()), var_context(varid, "write"));
}

void ModelNetcdfFile::check_block(int varid, std::span<const std::size_t> start,
                                  std::span<const std::size_t> count, std::size_t values) const {
  std::size_t n = 1;
  for (const std::size_t c : count) n *= c;
  if (start.size() != count.size() || values != n) {
    throw make_error(ErrorCode::kInternal, "{}: block of {} values for {} samples",
                     var_context(varid, "write"), values, n);
  }
}

void ModelNetcdfFile::put(int varid, std::span<const std::size_t> start,
                          std::span<const std::size_t> count, std::span<const float> values) {
  check_block(varid, start, count, values.size());
  std::lock_guard lock(netcdf_mutex());
  nc_check(nc_put_vara_float(ncid_, varid, start.data(), count.data(), values.data()),
           var_context(varid, "write"));
}

void ModelNetcdfFile::put(int varid, std::span<const std::size_t> start,
                          std::span<const std::size_t> count, std::span<const double> values) {
  check_block(varid, start, count, values.size());
  std::lock_guard lock(netcdf_mutex());
  nc_check(nc_put_vara_double(ncid_, varid, start.data(), count.data(), values.data()),
           var_context(varid, "write"));
}

void ModelNetcdfFile::put_text(int varid, std::span<const std::size_t> start,
                               std::span<const std::size_t> count, std::string_view values) {
  check_block(varid, start, count, values.size());
  std::lock_guard lock(netcdf_mutex());
  nc_check(nc_put_vara_text(ncid_, varid, start.data(), count.data(), values.data()),
           var_context(varid, "write"));
}

std::uint64_t ModelNetcdfFile::commit() {
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
