// SPDX-License-Identifier: Apache-2.0
// Helpers shared by the tests of the sample generator: generate a small dataset into a
// temporary directory and read it back with the netCDF C API (under netcdf_mutex()).
#pragma once

#include <gtest/gtest.h>
#include <netcdf.h>

#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "ingest/netcdf_call.h"
#include "synthetic/sample_dataset.h"
#include "support/temp_dir.h"

namespace strielad::testing {

// A read-only netCDF file; every call holds netcdf_mutex().
class NcFile {
 public:
  explicit NcFile(const std::filesystem::path& path) : path_(path) {
    std::lock_guard lock(ingest::netcdf_mutex());
    ingest::nc_check(nc_open(path.c_str(), NC_NOWRITE, &ncid_), path.string());
  }
  ~NcFile() {
    std::lock_guard lock(ingest::netcdf_mutex());
    nc_close(ncid_);
  }
  NcFile(const NcFile&) = delete;
  NcFile& operator=(const NcFile&) = delete;

  int id() const { return ncid_; }

  int varid(const std::string& name) const {
    std::lock_guard lock(ingest::netcdf_mutex());
    int v = -1;
    ingest::nc_check(nc_inq_varid(ncid_, name.c_str(), &v), path_.string() + ": " + name);
    return v;
  }
  bool has_var(const std::string& name) const {
    std::lock_guard lock(ingest::netcdf_mutex());
    int v = -1;
    return nc_inq_varid(ncid_, name.c_str(), &v) == NC_NOERR;
  }
  std::size_t dim_length(const std::string& name) const {
    std::lock_guard lock(ingest::netcdf_mutex());
    int d = -1;
    std::size_t len = 0;
    ingest::nc_check(nc_inq_dimid(ncid_, name.c_str(), &d), path_.string() + ": dim " + name);
    ingest::nc_check(nc_inq_dimlen(ncid_, d, &len), path_.string() + ": dim " + name);
    return len;
  }
  std::vector<std::string> dim_names(const std::string& var) const {
    const int v = varid(var);
    std::lock_guard lock(ingest::netcdf_mutex());
    int ndims = 0;
    int dims[NC_MAX_VAR_DIMS];
    ingest::nc_check(nc_inq_var(ncid_, v, nullptr, nullptr, &ndims, dims, nullptr), var);
    std::vector<std::string> names;
    for (int i = 0; i < ndims; ++i) {
      char name[NC_MAX_NAME + 1] = {};
      ingest::nc_check(nc_inq_dimname(ncid_, dims[i], name), var);
      names.emplace_back(name);
    }
    return names;
  }
  std::vector<double> doubles(const std::string& var) const {
    const int v = varid(var);
    std::vector<double> out(element_count(var));
    std::lock_guard lock(ingest::netcdf_mutex());
    ingest::nc_check(nc_get_var_double(ncid_, v, out.data()), var);
    return out;
  }
  std::vector<float> floats(const std::string& var) const {
    const int v = varid(var);
    std::vector<float> out(element_count(var));
    std::lock_guard lock(ingest::netcdf_mutex());
    ingest::nc_check(nc_get_var_float(ncid_, v, out.data()), var);
    return out;
  }
  // One (time t, level k) slab of a var(time, height, lat, lon).
  std::vector<float> level(const std::string& var, std::size_t t, std::size_t k) const {
    const int v = varid(var);
    const std::size_t ny = dim_length("lat"), nx = dim_length("lon");
    std::vector<float> out(ny * nx);
    const std::size_t start[4] = {t, k, 0, 0}, count[4] = {1, 1, ny, nx};
    std::lock_guard lock(ingest::netcdf_mutex());
    ingest::nc_check(nc_get_vara_float(ncid_, v, start, count, out.data()), var);
    return out;
  }
  // All levels of one time step of a var(time, height, lat, lon), level 0 first.
  std::vector<float> step(const std::string& var, std::size_t t) const {
    const int v = varid(var);
    const std::size_t nz = dim_length("height"), ny = dim_length("lat"), nx = dim_length("lon");
    std::vector<float> out(nz * ny * nx);
    const std::size_t start[4] = {t, 0, 0, 0}, count[4] = {1, nz, ny, nx};
    std::lock_guard lock(ingest::netcdf_mutex());
    ingest::nc_check(nc_get_vara_float(ncid_, v, start, count, out.data()), var);
    return out;
  }
  bool has_att(const std::string& var, const std::string& att) const {
    const int v = var.empty() ? NC_GLOBAL : varid(var);
    std::lock_guard lock(ingest::netcdf_mutex());
    std::size_t len = 0;
    return nc_inq_attlen(ncid_, v, att.c_str(), &len) == NC_NOERR;
  }
  std::string text_att(const std::string& var, const std::string& att) const {
    const int v = var.empty() ? NC_GLOBAL : varid(var);
    std::lock_guard lock(ingest::netcdf_mutex());
    std::size_t len = 0;
    nc_type type = NC_NAT;
    ingest::nc_check(nc_inq_att(ncid_, v, att.c_str(), &type, &len), var + ":" + att);
    EXPECT_EQ(type, NC_CHAR) << var << ":" << att;
    std::string out(len, '\0');
    ingest::nc_check(nc_get_att_text(ncid_, v, att.c_str(), out.data()), var + ":" + att);
    return out;
  }

 private:
  std::size_t element_count(const std::string& var) const {
    std::size_t n = 1;
    for (const auto& d : dim_names(var)) n *= dim_length(d);
    return n;
  }

  std::filesystem::path path_;
  int ncid_ = -1;
};

// A small spec: clouds and dense fields, few levels, quick to write.
inline synthetic::SampleSpec small_spec(Dims3 dims = Dims3{48, 40, 30}, std::size_t steps = 1) {
  synthetic::SampleSpec spec;
  spec.dims = dims;
  spec.steps = steps;
  return spec;
}

// Writes `spec` into a fresh temporary directory that lives as long as the result.
struct GeneratedSample {
  TempDir dir;
  synthetic::SampleResult result;

  explicit GeneratedSample(const synthetic::SampleSpec& spec)
      : result(synthetic::write_sample_dataset(spec, dir.path())) {}
  const std::filesystem::path& file(std::size_t i = 0) const { return result.files.at(i).path; }
};

inline double nonzero_fraction(const std::vector<float>& values) {
  std::size_t n = 0;
  for (const float v : values) n += v != 0.0f;
  return values.empty() ? 0.0 : static_cast<double>(n) / static_cast<double>(values.size());
}

}  // namespace strielad::testing
