// SPDX-License-Identifier: Apache-2.0
// A NetCDF-4 (or classic 64-bit-offset) file the model-like samples are written into: built under
// temporary_sibling(path) and renamed onto `path` by commit() only, as SampleFileWriter
// does; small helpers for dimensions, variables and attributes. Every nc_* call holds
// netcdf_mutex(); errors throw naming the file and the dimension, variable or attribute.
#pragma once

#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace strielad::synthetic {

class ModelNetcdfFile {
 public:
  enum class Type { kFloat, kDouble, kChar };
  // NetCDF-4 (HDF5, chunked and deflated at will) or the classic 64-bit-offset format
  // WRF writes by default (no chunking, no deflate).
  enum class Format { kNetcdf4, kClassic64BitOffset };
  static constexpr int kGlobal = -1;  // the varid of global attributes (NC_GLOBAL)

  // Creates the temporary file (kIo naming the file when it cannot).
  explicit ModelNetcdfFile(std::filesystem::path path, Format format = Format::kNetcdf4);
  // Without commit(): closes and removes the temporary file.
  ~ModelNetcdfFile();
  ModelNetcdfFile(const ModelNetcdfFile&) = delete;
  ModelNetcdfFile& operator=(const ModelNetcdfFile&) = delete;

  // Define mode. length 0: the unlimited dimension.
  int dimension(const std::string& name, std::size_t length);
  int variable(const std::string& name, Type type, std::initializer_list<int> dims);
  // Chunks of one horizontal plane (the last two dimensions whole, the others 1),
  // deflated with shuffle at `deflate` > 0.
  void chunk_by_plane(int varid, std::span<const std::size_t> plane_shape, int deflate);
  void text(int varid, const std::string& name, std::string_view value);
  void number(int varid, const std::string& name, double value);
  void unsigned_number(int varid, const std::string& name, std::uint64_t value);
  void float_number(int varid, const std::string& name, float value);  // NC_FLOAT
  void integer(int varid, const std::string& name, int value);         // NC_INT
  void end_define();

  // Data mode: a whole variable, or the block at `start` of shape `count`.
  void put(int varid, std::span<const double> values);
  void put(int varid, std::span<const float> values);
  void put(int varid, std::span<const std::size_t> start, std::span<const std::size_t> count,
           std::span<const float> values);
  void put(int varid, std::span<const std::size_t> start, std::span<const std::size_t> count,
           std::span<const double> values);

  // Characters of a char variable: the block at `start` of shape `count`.
  void put_text(int varid, std::span<const std::size_t> start, std::span<const std::size_t> count,
                std::string_view values);

  // Closes, fsyncs and renames the file onto its path; returns its size in bytes.
  std::uint64_t commit();
  const std::filesystem::path& path() const { return path_; }

 private:
  void check_block(int varid, std::span<const std::size_t> start,
                   std::span<const std::size_t> count, std::size_t values) const;
  std::string context(std::string_view what) const;
  std::string var_context(int varid, std::string_view what) const;

  std::filesystem::path path_, temp_path_;
  int ncid_ = -1;
  std::vector<std::string> var_names_;  // by varid
  bool committed_ = false;
};

}  // namespace strielad::synthetic
