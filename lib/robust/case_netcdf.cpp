// SPDX-License-Identifier: Apache-2.0
#include "robust/case_netcdf.h"

#include <netcdf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <string>
#include <vector>

#include "core/error.h"
#include "ingest/netcdf_call.h"

namespace strielad::robust {
namespace {

using ingest::nc_check;

void put_text(int ncid, int varid, const char* name, const std::string& value,
              const std::string& context) {
  nc_check(nc_put_att_text(ncid, varid, name, value.size(), value.data()),
           context + ": attribute " + name);
}

int define_coordinate(int ncid, const char* name, std::size_t length,
                      const std::vector<std::pair<const char*, std::string>>& attributes,
                      const std::string& context, nc_type type = NC_DOUBLE) {
  int dimid = -1, varid = -1;
  nc_check(nc_def_dim(ncid, name, length, &dimid), context + ": dimension " + name);
  nc_check(nc_def_var(ncid, name, type, 1, &dimid, &varid), context + ": variable " + name);
  for (const auto& [key, value] : attributes) put_text(ncid, varid, key, value, context);
  return varid;
}

void write_all(const ExtremeCase& c, int ncid, const std::string& context) {
  const CaseInput& in = c.input;
  const int v_time = define_coordinate(
      ncid, "time", in.time.size(),
      {{"standard_name", "time"}, {"units", "seconds since 2020-01-01 00:00:00"},
       {"calendar", "standard"}},
      context);
  const char* z_name = in.integer_pressure_levels ? "plev" : "height";
  const int v_z =
      in.integer_pressure_levels
          ? define_coordinate(ncid, z_name, in.z.size(),
                              {{"standard_name", "air_pressure"}, {"units", "hPa"},
                               {"positive", "down"}, {"axis", "Z"}},
                              context, NC_INT)
          : define_coordinate(ncid, z_name, in.z.size(),
                              {{"standard_name", "height"}, {"units", "m"}, {"positive", "up"},
                               {"axis", "Z"}},
                              context);
  const int v_lat = define_coordinate(
      ncid, "lat", in.lat.size(), {{"standard_name", "latitude"}, {"units", "degrees_north"}},
      context);
  const int v_lon = define_coordinate(
      ncid, "lon", in.lon.size(), {{"standard_name", "longitude"}, {"units", "degrees_east"}},
      context);
  std::array<int, 4> dims{};
  const char* names[4] = {"time", z_name, "lat", "lon"};
  for (int d = 0; d < 4; ++d) {
    nc_check(nc_inq_dimid(ncid, names[d], &dims[d]), context + ": dimension " + names[d]);
  }
  const nc_type type = in.type == SourceType::kFloat    ? NC_FLOAT
                       : in.type == SourceType::kDouble ? NC_DOUBLE
                                                        : NC_SHORT;
  int v_f = -1;
  nc_check(nc_def_var(ncid, "f", type, 4, dims.data(), &v_f), context + ": variable f");
  // Chunks of at most 64 x 64 samples per level: an unwritten huge variable takes no
  // space, and reading a slab of it touches only chunks that read as fill.
  const std::array<std::size_t, 4> chunks{1, 1, std::min<std::size_t>(in.lat.size(), 64),
                                          std::min<std::size_t>(in.lon.size(), 64)};
  nc_check(nc_def_var_chunking(ncid, v_f, NC_CHUNKED, chunks.data()), context + ": chunking");
  put_text(ncid, v_f, "long_name", "robustness case " + c.name, context);
  put_text(ncid, v_f, "units", "1", context);
  if (in.fill_value) {
    nc_check(nc_put_att_double(ncid, v_f, "_FillValue", type, 1, &*in.fill_value),
             context + ": _FillValue");
  }
  if (in.scale_factor) {
    nc_check(nc_put_att_double(ncid, v_f, "scale_factor", NC_FLOAT, 1, &*in.scale_factor),
             context + ": scale_factor");
  }
  if (in.add_offset) {
    nc_check(nc_put_att_double(ncid, v_f, "add_offset", NC_FLOAT, 1, &*in.add_offset),
             context + ": add_offset");
  }
  nc_check(nc_enddef(ncid), context + ": enddef");
  nc_check(nc_put_var_double(ncid, v_time, in.time.data()), context + ": time");
  nc_check(nc_put_var_double(ncid, v_z, in.z.data()), context + ": height");
  nc_check(nc_put_var_double(ncid, v_lat, in.lat.data()), context + ": lat");
  nc_check(nc_put_var_double(ncid, v_lon, in.lon.data()), context + ": lon");
  if (in.values.empty()) return;
  // Written in the variable's own type, so that every value (denormals, NaN payloads,
  // +-0) reaches the file bit for bit.
  if (in.type == SourceType::kFloat) {
    std::vector<float> f(in.values.begin(), in.values.end());
    nc_check(nc_put_var_float(ncid, v_f, f.data()), context + ": write f");
  } else if (in.type == SourceType::kDouble) {
    nc_check(nc_put_var_double(ncid, v_f, in.values.data()), context + ": write f");
  } else {
    std::vector<short> s;
    s.reserve(in.values.size());
    for (double v : in.values) s.push_back(static_cast<short>(std::lround(v)));
    nc_check(nc_put_var_short(ncid, v_f, s.data()), context + ": write f");
  }
}

}  // namespace

void write_case_netcdf(const ExtremeCase& c, const std::filesystem::path& path) {
  const CaseInput& in = c.input;
  const std::size_t expected = in.time.size() * c.samples_per_step();
  if (!in.values.empty() && in.values.size() != expected) {
    throw make_error(ErrorCode::kInvalidArgument, "case {}: {} values for a {}x{}x{} grid of {} steps",
                     c.name, in.values.size(), c.nx(), c.ny(), c.nz(), in.time.size());
  }
  const std::string context = path.string();
  std::lock_guard lock(ingest::netcdf_mutex());
  int ncid = -1;
  nc_check(nc_create(path.c_str(), NC_NETCDF4 | NC_CLOBBER, &ncid), context + ": create");
  try {
    write_all(c, ncid, context);
  } catch (...) {
    nc_close(ncid);
    throw;
  }
  nc_check(nc_close(ncid), context + ": close");
}

}  // namespace strielad::robust
