// SPDX-License-Identifier: Apache-2.0
#include "ingest/netcdf_file.h"

#include <netcdf.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "core/error.h"
#include "ingest/classic_layout.h"
#include "ingest/netcdf_call.h"

namespace strielad::ingest {
NcFile::NcFile(const std::filesystem::path& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) {
    throw make_error(ErrorCode::kNotFound, "{}: no such file", path.string());
  }
  if (std::filesystem::is_directory(status)) {
    throw make_error(ErrorCode::kInvalidInput, "{}: is a directory, not a netCDF file",
                     path.string());
  }
  // Before netCDF-C reads the header: it allocates the counts a classic header declares
  // (a 460-byte file declaring 33 million dimensions made it calloc 1.7 GB, and
  // dereference null where that failed) and reads a truncated file's data as zeros.
  check_classic_header(path);
  int ncid = -1;
  const int rc = nc_open(path.c_str(), NC_NOWRITE, &ncid);
  if (rc == NC_NOERR) {
    ncid_ = ncid;
    return;
  }
  if (rc == ENOENT) {
    throw make_error(ErrorCode::kNotFound, "{}: no such file", path.string());
  }
  if (rc > 0) {
    // A system errno, but no fault of the system: check_classic_header above has read
    // the file's first bytes (a file the system refuses throws kIo there), and netCDF-C
    // also answers EINVAL or E2BIG for a header it cannot parse.
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: not a readable netCDF file (its header is damaged or not netCDF): "
                     "netCDF-C says '{}'",
                     path.string(), std::strerror(rc));
  }
  throw make_error(ErrorCode::kInvalidInput,
                   "{}: not a readable netCDF file (truncated or not netCDF?): {}",
                   path.string(), nc_strerror(rc));
}

NcFile::NcFile(NcFile&& other) noexcept : ncid_(other.ncid_) { other.ncid_ = -1; }

NcFile& NcFile::operator=(NcFile&& other) noexcept {
  if (this != &other) {
    if (ncid_ >= 0) nc_close(ncid_);
    ncid_ = other.ncid_;
    other.ncid_ = -1;
  }
  return *this;
}

NcFile::~NcFile() {
  if (ncid_ >= 0) nc_close(ncid_);
}

int NcFile::format() const {
  int format = 0;
  nc_check(nc_inq_format(ncid_, &format), "nc_inq_format");
  return format;
}

std::vector<int> all_groups(int grpid) {
  std::vector<int> out{grpid};
  int count = 0;
  if (nc_inq_grps(grpid, &count, nullptr) != NC_NOERR || count <= 0) return out;
  std::vector<int> children(static_cast<std::size_t>(count));
  nc_check(nc_inq_grps(grpid, &count, children.data()), "nc_inq_grps");
  for (int child : children) {
    auto sub = all_groups(child);
    out.insert(out.end(), sub.begin(), sub.end());
  }
  return out;
}

std::string group_path(int grpid) {
  std::size_t len = 0;
  nc_check(nc_inq_grpname_full(grpid, &len, nullptr), "nc_inq_grpname_full");
  std::string name(len, '\0');
  nc_check(nc_inq_grpname_full(grpid, &len, name.data()), "nc_inq_grpname_full");
  name.resize(std::strlen(name.c_str()));
  while (!name.empty() && name.front() == '/') name.erase(name.begin());
  return name;
}

std::optional<int> parent_group(int grpid) {
  int parent = -1;
  if (nc_inq_grp_parent(grpid, &parent) != NC_NOERR) return std::nullopt;
  return parent;
}

std::string variable_name(int grpid, int varid) {
  char name[NC_MAX_NAME + 1] = {};
  nc_check(nc_inq_varname(grpid, varid, name), "nc_inq_varname");
  return name;
}

std::string dimension_name(int grpid, int dimid) {
  char name[NC_MAX_NAME + 1] = {};
  nc_check(nc_inq_dimname(grpid, dimid, name), "nc_inq_dimname");
  return name;
}

std::size_t dimension_length(int grpid, int dimid) {
  std::size_t len = 0;
  nc_check(nc_inq_dimlen(grpid, dimid, &len), "nc_inq_dimlen");
  return len;
}

std::vector<int> variable_dimids(int grpid, int varid) {
  int ndims = 0;
  nc_check(nc_inq_varndims(grpid, varid, &ndims), "nc_inq_varndims");
  std::vector<int> dimids(static_cast<std::size_t>(ndims));
  if (ndims > 0) nc_check(nc_inq_vardimid(grpid, varid, dimids.data()), "nc_inq_vardimid");
  return dimids;
}

int variable_type(int grpid, int varid) {
  nc_type type = NC_NAT;
  nc_check(nc_inq_vartype(grpid, varid, &type), "nc_inq_vartype");
  return type;
}

int variable_count(int grpid) {
  int nvars = 0;
  nc_check(nc_inq_nvars(grpid, &nvars), "nc_inq_nvars");
  return nvars;
}

bool is_unlimited_dimension(int grpid, int dimid) {
  for (std::optional<int> g = grpid; g; g = parent_group(*g)) {
    int count = 0;
    if (nc_inq_unlimdims(*g, &count, nullptr) != NC_NOERR || count <= 0) continue;
    std::vector<int> ids(static_cast<std::size_t>(count));
    if (nc_inq_unlimdims(*g, &count, ids.data()) != NC_NOERR) continue;
    for (int id : ids) {
      if (id == dimid) return true;
    }
  }
  return false;
}

std::optional<VariableRef> find_coordinate_variable(int grpid, int dimid) {
  const std::string name = dimension_name(grpid, dimid);
  for (std::optional<int> g = grpid; g; g = parent_group(*g)) {
    int varid = -1;
    if (nc_inq_varid(*g, name.c_str(), &varid) != NC_NOERR) continue;
    int ndims = 0;
    if (nc_inq_varndims(*g, varid, &ndims) != NC_NOERR || ndims != 1) continue;
    int vdim = -1;
    if (nc_inq_vardimid(*g, varid, &vdim) != NC_NOERR || vdim != dimid) continue;
    return VariableRef{*g, varid};
  }
  return std::nullopt;
}

std::vector<double> read_all_as_double(int grpid, int varid, std::string_view context) {
  std::size_t count = 1;
  for (int dimid : variable_dimids(grpid, varid)) count *= dimension_length(grpid, dimid);
  std::vector<double> values(count);
  if (count > 0) nc_check(nc_get_var_double(grpid, varid, values.data()), context);
  return values;
}

std::string_view nc_type_name(int type) noexcept {
  switch (type) {
    case NC_BYTE: return "byte";
    case NC_CHAR: return "char";
    case NC_SHORT: return "short";
    case NC_INT: return "int";
    case NC_FLOAT: return "float";
    case NC_DOUBLE: return "double";
    case NC_UBYTE: return "ubyte";
    case NC_USHORT: return "ushort";
    case NC_UINT: return "uint";
    case NC_INT64: return "int64";
    case NC_UINT64: return "uint64";
    case NC_STRING: return "string";
    default: return "user-defined";
  }
}

std::size_t nc_type_size(int type) noexcept {
  switch (type) {
    case NC_BYTE:
    case NC_UBYTE: return 1;
    case NC_SHORT:
    case NC_USHORT: return 2;
    case NC_INT:
    case NC_UINT:
    case NC_FLOAT: return 4;
    case NC_DOUBLE:
    case NC_INT64:
    case NC_UINT64: return 8;
    default: return 0;
  }
}

bool is_numeric_type(int type) noexcept { return nc_type_size(type) > 0; }

bool is_integer_type(int type) noexcept {
  return is_numeric_type(type) && type != NC_FLOAT && type != NC_DOUBLE;
}

}  // namespace strielad::ingest
