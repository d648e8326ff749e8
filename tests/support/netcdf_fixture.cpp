// SPDX-License-Identifier: Apache-2.0
#include "support/netcdf_fixture.h"

#include <map>
#include <stdexcept>
#include <utility>

namespace strielad::testing {
namespace {

void check(int status, const std::string& what) {
  if (status != NC_NOERR) {
    throw std::runtime_error("netcdf fixture: " + what + ": " + nc_strerror(status));
  }
}

// "grp/sub/name" -> ("grp/sub", "name").
std::pair<std::string, std::string> split(const std::string& full) {
  const auto slash = full.rfind('/');
  if (slash == std::string::npos) return {"", full};
  return {full.substr(0, slash), full.substr(slash + 1)};
}

int group_id(int ncid, const std::string& path, std::map<std::string, int>& groups) {
  if (path.empty()) return ncid;
  if (auto it = groups.find(path); it != groups.end()) return it->second;
  const auto [parent_path, name] = split(path);
  const int parent = group_id(ncid, parent_path, groups);
  int grp = -1;
  check(nc_def_grp(parent, name.c_str(), &grp), "nc_def_grp " + path);
  groups[path] = grp;
  return grp;
}

void put_attribute(int ncid, int varid, const NcAttr& a) {
  if (a.type == NC_CHAR) {
    check(nc_put_att_text(ncid, varid, a.name.c_str(), a.text.size(), a.text.c_str()), a.name);
  } else if (a.type == NC_STRING) {
    const char* value = a.text.c_str();
    check(nc_put_att_string(ncid, varid, a.name.c_str(), 1, &value), a.name);
  } else {
    check(nc_put_att_double(ncid, varid, a.name.c_str(), a.type, a.values.size(),
                            a.values.data()),
          a.name);
  }
}

}  // namespace

NcAttr NcAttr::text_value(std::string name, std::string value) {
  return NcAttr{std::move(name), NC_CHAR, std::move(value), {}};
}
NcAttr NcAttr::string_value(std::string name, std::string value) {
  return NcAttr{std::move(name), NC_STRING, std::move(value), {}};
}
NcAttr NcAttr::number(std::string name, int type, std::vector<double> values) {
  return NcAttr{std::move(name), type, {}, std::move(values)};
}

std::vector<std::string> SimpleGrid::dims() const {
  if (with_time) return {"time", "lev", "lat", "lon"};
  return {"lev", "lat", "lon"};
}

NetcdfFixture::NetcdfFixture(int cmode) : cmode_(cmode) {}

NetcdfFixture& NetcdfFixture::dimension(const std::string& name, std::size_t length,
                                        bool unlimited) {
  dims_.push_back({name, length, unlimited});
  return *this;
}

NetcdfFixture& NetcdfFixture::coordinate(const std::string& name, std::vector<double> values,
                                         std::vector<NcAttr> attrs, int type, bool unlimited) {
  dimension(name, values.size(), unlimited);
  const std::string dim = split(name).second;
  vars_.push_back({name, type, {dim}, std::move(values), std::move(attrs), {}});
  return *this;
}

NetcdfFixture& NetcdfFixture::variable(const std::string& name, int type,
                                       std::vector<std::string> dims, std::vector<double> data,
                                       std::vector<NcAttr> attrs, VarStorage storage) {
  vars_.push_back({name, type, std::move(dims), std::move(data), std::move(attrs), std::move(storage)});
  return *this;
}

NetcdfFixture& NetcdfFixture::global_attribute(NcAttr attr) {
  globals_.push_back(std::move(attr));
  return *this;
}

NetcdfFixture& NetcdfFixture::grid(const SimpleGrid& g) {
  const std::string p = g.group.empty() ? std::string() : g.group + "/";
  if (g.with_time) {
    coordinate(p + "time", g.time,
               {NcAttr::text_value("standard_name", "time"),
                NcAttr::text_value("units", g.time_units),
                NcAttr::text_value("calendar", g.calendar)},
               NC_DOUBLE, g.time_unlimited);
  }
  coordinate(p + "lev", g.lev,
             {NcAttr::text_value("long_name", "pressure level"),
              NcAttr::text_value("units", g.lev_units), NcAttr::text_value("positive", "down"),
              NcAttr::text_value("axis", "Z")});
  coordinate(p + "lat", g.lat,
             {NcAttr::text_value("standard_name", "latitude"),
              NcAttr::text_value("units", "degrees_north")});
  coordinate(p + "lon", g.lon,
             {NcAttr::text_value("standard_name", "longitude"),
              NcAttr::text_value("units", "degrees_east")});
  return *this;
}

void NetcdfFixture::write(const std::filesystem::path& path) const {
  int ncid = -1;
  check(nc_create(path.c_str(), cmode_ | NC_CLOBBER, &ncid), "nc_create " + path.string());
  std::map<std::string, int> groups;
  std::map<std::string, std::size_t> lengths;  // by full dim name
  for (const auto& d : dims_) {
    const auto [gpath, name] = split(d.name);
    const int grp = group_id(ncid, gpath, groups);
    int dimid = -1;
    check(nc_def_dim(grp, name.c_str(), d.unlimited ? NC_UNLIMITED : d.length, &dimid),
          "nc_def_dim " + d.name);
    lengths[d.name] = d.length;
  }
  struct Defined {
    int grp, varid;
    std::vector<std::size_t> count;
  };
  std::vector<Defined> defined;
  for (const auto& v : vars_) {
    const auto [gpath, name] = split(v.name);
    const int grp = group_id(ncid, gpath, groups);
    std::vector<int> dimids;
    std::vector<std::size_t> count;
    for (const auto& dn : v.dims) {
      int dimid = -1;
      check(nc_inq_dimid(grp, dn.c_str(), &dimid), "dimension " + dn + " of " + v.name);
      dimids.push_back(dimid);
      // The length as declared: look it up in this group's path, then the ancestors.
      std::string g = gpath;
      for (;;) {
        const std::string key = g.empty() ? dn : g + "/" + dn;
        if (auto it = lengths.find(key); it != lengths.end()) {
          count.push_back(it->second);
          break;
        }
        if (g.empty()) throw std::runtime_error("netcdf fixture: unknown dimension " + dn);
        g = split(g).first;
      }
    }
    int varid = -1;
    check(nc_def_var(grp, name.c_str(), v.type, static_cast<int>(dimids.size()), dimids.data(),
                     &varid),
          "nc_def_var " + v.name);
    const VarStorage& st = v.storage;
    if (st.contiguous) {
      check(nc_def_var_chunking(grp, varid, NC_CONTIGUOUS, nullptr), "contiguous " + v.name);
    } else if (!st.chunks.empty()) {
      check(nc_def_var_chunking(grp, varid, NC_CHUNKED, st.chunks.data()), "chunking " + v.name);
    }
    if (st.deflate_level > 0) {
      check(nc_def_var_deflate(grp, varid, 0, 1, st.deflate_level), "deflate " + v.name);
    }
    if (st.endian != NC_ENDIAN_NATIVE) check(nc_def_var_endian(grp, varid, st.endian), "endian " + v.name);
    for (const auto& a : v.attrs) put_attribute(grp, varid, a);
    defined.push_back({grp, varid, count});
  }
  for (const auto& a : globals_) put_attribute(ncid, NC_GLOBAL, a);
  check(nc_enddef(ncid), "nc_enddef");
  for (std::size_t i = 0; i < vars_.size(); ++i) {
    const auto& v = vars_[i];
    if (v.data.empty()) continue;
    std::size_t n = 1;
    for (auto c : defined[i].count) n *= c;
    if (n != v.data.size()) {
      throw std::runtime_error("netcdf fixture: variable " + v.name + " needs " +
                               std::to_string(n) + " values, got " +
                               std::to_string(v.data.size()));
    }
    const std::vector<std::size_t> start(defined[i].count.size(), 0);
    const int rc = nc_put_vara_double(defined[i].grp, defined[i].varid, start.data(),
                                      defined[i].count.data(), v.data.data());
    if (rc != NC_ERANGE) check(rc, "nc_put_vara " + v.name);
  }
  check(nc_close(ncid), "nc_close");
}

std::vector<double> ramp(std::size_t n, double start, double step) {
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = start + static_cast<double>(i) * step;
  return out;
}

std::vector<double> with_repeated_first_column(const std::vector<double>& rows, std::size_t nx) {
  std::vector<double> out;
  out.reserve(rows.size() / nx * (nx + 1));
  for (std::size_t r = 0; r < rows.size() / nx; ++r) {
    out.insert(out.end(), rows.begin() + static_cast<std::ptrdiff_t>(r * nx),
               rows.begin() + static_cast<std::ptrdiff_t>((r + 1) * nx));
    out.push_back(rows[r * nx]);
  }
  return out;
}

std::vector<double> read_vara(const std::filesystem::path& path, const std::string& variable,
                              std::vector<std::size_t> start, std::vector<std::size_t> count) {
  int ncid = -1;
  check(nc_open(path.c_str(), NC_NOWRITE, &ncid), "nc_open " + path.string());
  const auto [gpath, name] = split(variable);
  int grp = ncid;
  if (!gpath.empty()) check(nc_inq_grp_full_ncid(ncid, ("/" + gpath).c_str(), &grp), gpath);
  int varid = -1;
  check(nc_inq_varid(grp, name.c_str(), &varid), variable);
  std::size_t n = 1;
  for (auto c : count) n *= c;
  std::vector<double> out(n);
  const int rc = nc_get_vara_double(grp, varid, start.data(), count.data(), out.data());
  nc_close(ncid);
  check(rc, "nc_get_vara " + variable);
  return out;
}

void copy_truncated(const std::filesystem::path& from, const std::filesystem::path& to,
                    std::uintmax_t size) {
  std::filesystem::copy_file(from, to, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::permissions(to, std::filesystem::perms::owner_write,
                               std::filesystem::perm_options::add);
  std::filesystem::resize_file(to, size);
}

NetcdfValues read_netcdf_variable(const std::filesystem::path& file, const std::string& name) {
  const std::string what = file.string() + ": " + name;
  int nc = 0, var = 0, ndims = 0;
  check(nc_open(file.c_str(), NC_NOWRITE, &nc), what);
  NetcdfValues out;
  try {
    check(nc_inq_varid(nc, name.c_str(), &var), what);
    check(nc_inq_varndims(nc, var, &ndims), what);
    std::vector<int> dims(static_cast<std::size_t>(ndims));
    check(nc_inq_vardimid(nc, var, dims.data()), what);
    std::size_t count = 1;
    for (int d : dims) {
      std::size_t n = 0;
      check(nc_inq_dimlen(nc, d, &n), what);
      out.shape.push_back(n);
      count *= n;
    }
    out.values.resize(count);
    check(nc_get_var_double(nc, var, out.values.data()), what);
  } catch (...) {
    nc_close(nc);
    throw;
  }
  nc_close(nc);
  return out;
}

}  // namespace strielad::testing
