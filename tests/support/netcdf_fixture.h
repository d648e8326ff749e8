// SPDX-License-Identifier: Apache-2.0
// Writes small NetCDF files for tests with the netCDF C API: dimensions, coordinate
// variables, data variables (in groups too: "grp1/T"), attributes of any type.
//
//   NetcdfFixture(NC_NETCDF4)
//       .grid(SimpleGrid{})                      // time, lev, lat, lon with CF attributes
//       .variable("T", NC_FLOAT, {"time", "lev", "lat", "lon"}, ramp(24),
//                 {NcAttr::number("_FillValue", NC_FLOAT, {-999})})
//       .write(dir / "t.nc");
#pragma once

#include <netcdf.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace strielad::testing {

struct NcAttr {
  std::string name;
  int type = NC_CHAR;  // NC_CHAR, NC_STRING or a numeric type
  std::string text;
  std::vector<double> values;

  static NcAttr text_value(std::string name, std::string value);    // NC_CHAR
  static NcAttr string_value(std::string name, std::string value);  // NC_STRING (netCDF-4)
  static NcAttr number(std::string name, int type, std::vector<double> values);
};

// A small rectilinear grid: coordinate variables with the usual CF attributes.
struct SimpleGrid {
  std::vector<double> time{0.0};
  std::vector<double> lev{1000.0, 850.0};
  std::vector<double> lat{-10.0, 0.0, 10.0};
  std::vector<double> lon{0.0, 10.0, 20.0, 30.0};  // regional: not round the Earth
  std::string time_units = "hours since 2000-01-01 00:00:00";
  std::string calendar = "standard";
  std::string lev_units = "hPa";
  bool with_time = true;
  bool time_unlimited = true;
  std::string group;  // "" = root; else coordinates and dims go into this group

  std::size_t samples_per_step() const { return lev.size() * lat.size() * lon.size(); }
  std::size_t samples() const { return samples_per_step() * (with_time ? time.size() : 1); }
  // {"time", "lev", "lat", "lon"} (without "time" when !with_time).
  std::vector<std::string> dims() const;
};

// How a netCDF-4 variable is stored (nc_def_var_chunking, _deflate, _endian); the
// default leaves netCDF's choice.
struct VarStorage {
  bool contiguous = false;
  std::vector<std::size_t> chunks;  // chunk shape, one per dimension (empty: netCDF's)
  int deflate_level = 0;            // 0: no deflate filter
  int endian = 0;                   // NC_ENDIAN_NATIVE, NC_ENDIAN_LITTLE or NC_ENDIAN_BIG
};

class NetcdfFixture {
 public:
  // cmode for nc_create: NC_CLASSIC_MODEL, NC_64BIT_OFFSET, NC_NETCDF4, NC_64BIT_DATA...
  explicit NetcdfFixture(int cmode = NC_NETCDF4);

  // A dimension only (no coordinate variable). `length` is the number of records for
  // unlimited dimensions.
  NetcdfFixture& dimension(const std::string& name, std::size_t length, bool unlimited = false);
  // A dimension and its coordinate variable.
  NetcdfFixture& coordinate(const std::string& name, std::vector<double> values,
                            std::vector<NcAttr> attrs = {}, int type = NC_DOUBLE,
                            bool unlimited = false);
  NetcdfFixture& variable(const std::string& name, int type, std::vector<std::string> dims,
                          std::vector<double> data, std::vector<NcAttr> attrs = {},
                          VarStorage storage = {});
  NetcdfFixture& global_attribute(NcAttr attr);
  NetcdfFixture& grid(const SimpleGrid& grid);

  // Throws std::runtime_error on any netCDF failure.
  void write(const std::filesystem::path& path) const;

 private:
  struct Dim {
    std::string name;  // may be "group/name"
    std::size_t length;
    bool unlimited;
  };
  struct Var {
    std::string name;  // may be "group/name"
    int type;
    std::vector<std::string> dims;
    std::vector<double> data;
    std::vector<NcAttr> attrs;
    VarStorage storage;
  };
  int cmode_;
  std::vector<Dim> dims_;
  std::vector<Var> vars_;
  std::vector<NcAttr> globals_;
};

// 0, 1, 2, ... scaled: start + i * step.
std::vector<double> ramp(std::size_t n, double start = 0.0, double step = 1.0);

// Rows of `nx` values (x fastest) with each row's first value repeated at its end: what a
// store or catalog holds for a periodic longitude axis whose file lacks the repeated
// meridian.
std::vector<double> with_repeated_first_column(const std::vector<double>& rows, std::size_t nx);

// Reads a hyperslab of `variable` ("T" or "grp1/T") directly with nc_get_vara_double.
std::vector<double> read_vara(const std::filesystem::path& path, const std::string& variable,
                              std::vector<std::size_t> start, std::vector<std::size_t> count);

// Copies `from` to `to` and truncates the copy to `size` bytes.
void copy_truncated(const std::filesystem::path& from, const std::filesystem::path& to,
                    std::uintmax_t size);

// A whole variable of `file` in double (netCDF's own conversion), read with netCDF itself,
// and its dimension lengths. Throws std::runtime_error naming the file and variable.
struct NetcdfValues {
  std::vector<double> values;
  std::vector<std::size_t> shape;
};
NetcdfValues read_netcdf_variable(const std::filesystem::path& file, const std::string& name);

}  // namespace strielad::testing
