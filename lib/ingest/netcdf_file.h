// SPDX-License-Identifier: Apache-2.0
// Small RAII and query helpers over the netCDF-C API used by the scanner and the slab
// reader. Every function here calls into netCDF: the caller must hold netcdf_mutex().
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace strielad::ingest {

// An open, read-only netCDF file (any format netCDF-C reads). Closed on destruction.
class NcFile {
 public:
  NcFile() = default;
  // Throws kNotFound when the file does not exist, kIo when the system cannot open or
  // read it, and kInvalidInput when it is a classic-format file shorter than its header
  // says (classic_layout.h; checked before netCDF-C reads it) or (with netCDF's message)
  // not a readable netCDF file, including the damaged headers netCDF-C answers with a
  // system errno (EINVAL).
  explicit NcFile(const std::filesystem::path& path);
  NcFile(NcFile&& other) noexcept;
  NcFile& operator=(NcFile&& other) noexcept;
  NcFile(const NcFile&) = delete;
  NcFile& operator=(const NcFile&) = delete;
  ~NcFile();

  int id() const { return ncid_; }
  bool is_open() const { return ncid_ >= 0; }
  // NC_FORMAT_CLASSIC, NC_FORMAT_64BIT_OFFSET, NC_FORMAT_CDF5, NC_FORMAT_NETCDF4...
  int format() const;

 private:
  int ncid_ = -1;
};

// The group and all its descendants, depth first, parents before children.
std::vector<int> all_groups(int grpid);

// "" for the root group, else the full path without the leading slash ("grp1/sub").
std::string group_path(int grpid);

// The parent group, or nullopt for the root group.
std::optional<int> parent_group(int grpid);

std::string variable_name(int grpid, int varid);
std::string dimension_name(int grpid, int dimid);
std::size_t dimension_length(int grpid, int dimid);
std::vector<int> variable_dimids(int grpid, int varid);
int variable_type(int grpid, int varid);
int variable_count(int grpid);  // variables of this group only (varids 0..n-1)

// True when `dimid` is an unlimited dimension of `grpid` or one of its ancestors.
bool is_unlimited_dimension(int grpid, int dimid);

struct VariableRef {
  int grpid = -1;
  int varid = -1;
};

// The coordinate variable of a dimension seen from `grpid`: a one-dimensional variable
// over `dimid` named like the dimension, looked up in `grpid` and then its ancestors.
std::optional<VariableRef> find_coordinate_variable(int grpid, int dimid);

// Reads a whole variable converted to double.
std::vector<double> read_all_as_double(int grpid, int varid, std::string_view context);

// netCDF type names as ncdump prints them: "byte", "short", "float", "string"...
std::string_view nc_type_name(int type) noexcept;
std::size_t nc_type_size(int type) noexcept;  // 0 for non-atomic or text types
bool is_numeric_type(int type) noexcept;      // byte..uint64 plus float/double
bool is_integer_type(int type) noexcept;

}  // namespace strielad::ingest
