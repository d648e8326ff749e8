// SPDX-License-Identifier: Apache-2.0
// The CF-NetCDF DEM reader (scenery/dem_source.h): windowed, strided reads with nc_get_vars.
#include <netcdf.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <mutex>
#include <optional>

#include "core/error.h"
#include "geo/cf_grid_mapping.h"
#include "scenery/dem_source.h"
#include "geo/grid_projection.h"
#include "ingest/cf_attributes.h"
#include "ingest/grid_mapping_reader.h"
#include "ingest/netcdf_call.h"
#include "ingest/netcdf_file.h"
#include "ingest/variable_meta.h"

namespace strielad::geo {
namespace {

using namespace ingest;

// Names of surface height variables tried in order when no variable is given (after
// standard_name surface_altitude).
constexpr std::array<const char*, 6> kHeightNames = {"HSURF", "z_ifc", "topography_c",
                                                     "orog", "elevation", "topo"};

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

bool is_longitude(int grp, int var) {
  const auto sn = text_attribute_or_empty(grp, var, "standard_name");
  const auto units = lower(text_attribute_or_empty(grp, var, "units"));
  return sn == "longitude" || units == "degrees_east" || units == "degree_east" ||
         units == "degrees_e" || units == "degreese";
}
bool is_latitude(int grp, int var) {
  const auto sn = text_attribute_or_empty(grp, var, "standard_name");
  const auto units = lower(text_attribute_or_empty(grp, var, "units"));
  return sn == "latitude" || units == "degrees_north" || units == "degree_north" ||
         units == "degrees_n" || units == "degreesn";
}

// Linear interpolation (and extrapolation) of an axis at a fractional index.
double axis_at(const std::vector<double>& axis, double index) {
  if (axis.size() == 1) return axis[0];
  const double clamped = std::clamp(index, 0.0, double(axis.size() - 1));
  auto i = static_cast<std::size_t>(std::floor(clamped));
  if (i >= axis.size() - 1) i = axis.size() - 2;
  const double t = index - double(i);
  return axis[i] + t * (axis[i + 1] - axis[i]);
}

class NetcdfDem final : public DemSource {
 public:
  NetcdfDem(const std::filesystem::path& path, const std::string& variable) : path_(path) {
    std::lock_guard lock(netcdf_mutex());
    try {
      open(variable);
    } catch (...) {
      file_ = NcFile();  // closed under the lock
      throw;
    }
  }
  ~NetcdfDem() override {
    std::lock_guard lock(netcdf_mutex());
    file_ = NcFile();
  }

  void open(const std::string& variable) {
    file_ = NcFile(path_);
    const int grp = file_.id();
    varid_ = find_variable(grp, variable);
    name_ = variable_name(grp, varid_);
    const auto dimids = variable_dimids(grp, varid_);
    std::vector<std::size_t> lengths;
    std::string shape;
    for (const int d : dimids) {
      lengths.push_back(dimension_length(grp, d));
      shape += fmt::format("{}{}={}", shape.empty() ? "" : ", ", dimension_name(grp, d),
                           lengths.back());
    }
    bool leading_ok = dimids.size() >= 2;
    for (std::size_t i = 0; leading_ok && i + 2 < dimids.size(); ++i) leading_ok = lengths[i] == 1;
    if (!leading_ok) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: variable {} has dimensions ({}): a DEM must be 2-D (leading "
                       "dimensions of length 1, like time, are allowed)",
                       describe(), name_, shape);
    }
    if (!is_numeric_type(variable_type(grp, varid_))) {
      throw make_error(ErrorCode::kInvalidInput, "{}: variable {} is not numeric", describe(), name_);
    }
    ndims_ = dimids.size();
    height_ = lengths[ndims_ - 2];
    width_ = lengths[ndims_ - 1];
    attributes_ = read_value_attributes(grp, varid_);
    const auto units = lower(text_attribute_or_empty(grp, varid_, "units"));
    if (units == "km" || units == "kilometre" || units == "kilometer" || units == "kilometres" ||
        units == "kilometers") {
      metres_per_unit_ = 1000.0;
    } else if (!units.empty() && units != "m" && units != "meter" && units != "metre" &&
               units != "meters" && units != "metres" && units != "gpm") {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: units '{}' are not a height (m or km)", describe(), units);
    }
    georeference_axes(grp, dimids[ndims_ - 1], dimids[ndims_ - 2]);
    if (!proj_.empty()) check_auxiliary_coordinates(grp);
  }

  std::size_t width() const override { return width_; }
  std::size_t height() const override { return height_; }

  void georeference(std::span<const double> cols, std::span<const double> rows,
                    std::span<LonLat> out) const override {
    if (proj_.empty()) {
      for (std::size_t i = 0; i < out.size(); ++i) {
        out[i] = LonLat{axis_at(x_axis_, cols[i]), axis_at(y_axis_, rows[i])};
      }
      return;
    }
    const GridProjection& projection = GridProjection::for_this_thread(proj_);
    for (std::size_t i = 0; i < out.size(); ++i) {
      const auto g = projection.to_geographic(axis_at(x_axis_, cols[i]), axis_at(y_axis_, rows[i]));
      out[i] = LonLat{g[0], g[1]};
    }
  }

  std::vector<float> read(const DemWindow& w) const override {
    check_dem_window(w, width_, height_, describe());
    std::vector<std::size_t> start(ndims_, 0), count(ndims_, 1);
    std::vector<std::ptrdiff_t> stride(ndims_, 1);
    start[ndims_ - 2] = w.row0;
    start[ndims_ - 1] = w.col0;
    count[ndims_ - 2] = w.rows;
    count[ndims_ - 1] = w.cols;
    stride[ndims_ - 2] = stride[ndims_ - 1] = static_cast<std::ptrdiff_t>(w.stride);
    std::vector<double> raw(w.rows * w.cols);
    {
      std::lock_guard lock(netcdf_mutex());
      nc_check(nc_get_vars_double(file_.id(), varid_, start.data(), count.data(), stride.data(),
                                  raw.data()),
               describe());
    }
    const auto& a = attributes_;
    const auto fill = a.fill_value ? a.fill_value : a.default_fill;
    std::vector<float> out(raw.size());
    for (std::size_t i = 0; i < raw.size(); ++i) {
      const double v = raw[i];
      bool missing = !std::isfinite(v) || (fill && v == static_cast<double>(*fill));
      for (const auto m : a.missing_values) missing = missing || v == static_cast<double>(m);
      if (a.valid_min && v < static_cast<double>(*a.valid_min)) missing = true;
      if (a.valid_max && v > static_cast<double>(*a.valid_max)) missing = true;
      const double unpacked = v * a.scale_factor.value_or(1.0) + a.add_offset.value_or(0.0);
      out[i] = missing ? NAN : static_cast<float>(unpacked * metres_per_unit_);
    }
    return out;
  }

  std::string describe() const override {
    return name_.empty() ? path_.string() : path_.string() + ":" + name_;
  }
  std::string georeferencing() const override {
    return proj_.empty() ? std::string("longitude/latitude axes")
                         : fmt::format("grid mapping '{}' ({}) through PROJ: {}", mapping_variable_,
                                       mapping_name_, proj_);
  }

 private:
  int find_variable(int grp, const std::string& wanted) const {
    int varid = -1;
    if (!wanted.empty()) {
      if (nc_inq_varid(grp, wanted.c_str(), &varid) != NC_NOERR) {
        std::string names;
        for (int v = 0; v < variable_count(grp); ++v) {
          names += (names.empty() ? "" : ", ") + variable_name(grp, v);
        }
        throw make_error(ErrorCode::kNotFound, "{}: no variable '{}' (the file has: {})",
                         path_.string(), wanted, names);
      }
      return varid;
    }
    for (int v = 0; v < variable_count(grp); ++v) {
      if (text_attribute_or_empty(grp, v, "standard_name") == "surface_altitude") return v;
    }
    for (const char* name : kHeightNames) {
      if (nc_inq_varid(grp, name, &varid) == NC_NOERR) return varid;
    }
    throw make_error(ErrorCode::kNotFound,
                     "{}: no terrain height variable (standard_name surface_altitude, or named "
                     "HSURF, z_ifc, topography_c, orog, elevation); name one with --terrain-var",
                     path_.string());
  }

  void georeference_axes(int grp, int xdim, int ydim) {
    const auto xvar = find_coordinate_variable(grp, xdim);
    const auto yvar = find_coordinate_variable(grp, ydim);
    if (!xvar || !yvar) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: no georeferencing: dimensions {} and {} have no coordinate "
                       "variables (1-D longitude/latitude or map axes with a grid_mapping)",
                       describe(), dimension_name(grp, ydim), dimension_name(grp, xdim));
    }
    x_axis_ = read_all_as_double(xvar->grpid, xvar->varid, describe());
    y_axis_ = read_all_as_double(yvar->grpid, yvar->varid, describe());
    for (const auto* axis : {&x_axis_, &y_axis_}) {
      for (const double v : *axis) {
        if (!std::isfinite(v)) {
          throw make_error(ErrorCode::kInvalidInput, "{}: an axis holds a non-finite coordinate",
                           describe());
        }
      }
    }
    const auto axis = [&](const VariableRef& v, const std::vector<double>& values) {
      Axis a;
      a.name = variable_name(v.grpid, v.varid);
      a.units = text_attribute_or_empty(v.grpid, v.varid, "units");
      a.standard_name = text_attribute_or_empty(v.grpid, v.varid, "standard_name");
      a.values = values;
      return a;
    };
    const Axis x = axis(*xvar, x_axis_), y = axis(*yvar, y_axis_);
    std::optional<GridMapping> mapping = read_grid_mapping(grp, varid_, describe());
    if (mapping && lower(mapping->name) == "latitude_longitude") mapping.reset();
    if (mapping) {
      // The one mechanism that places stores: the CF attributes to a PROJ pipeline.
      proj_ = cf_grid_mapping_proj(*mapping, x, y, describe());
      mapping_variable_ = mapping->variable;
      mapping_name_ = mapping->name;
      (void)GridProjection::for_this_thread(proj_);  // kUnsupported now if PROJ rejects it
      return;
    }
    if (x.standard_name == "grid_longitude" || y.standard_name == "grid_latitude") {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: rotated grid axes {} and {} but no grid_mapping attribute naming a "
                       "rotated_latitude_longitude variable: where the pole is is unknown",
                       describe(), y.name, x.name);
    }
    if (!is_longitude(xvar->grpid, xvar->varid) || !is_latitude(yvar->grpid, yvar->varid)) {
      throw make_error(ErrorCode::kInvalidInput,
                       "{}: no georeferencing: axes {} and {} are neither longitude/latitude "
                       "(units degrees_east/degrees_north) nor map axes with a grid_mapping",
                       describe(), y.name, x.name);
    }
  }

  // The file's own 2-D lat/lon (the "coordinates" attribute) at the corners and centre
  // against the grid mapping: a mismatch means the grid_mapping is wrong.
  void check_auxiliary_coordinates(int grp) const {
    int lon_var = -1, lat_var = -1;
    for (const auto& name : split_words(text_attribute_or_empty(grp, varid_, "coordinates"))) {
      int v = -1;
      if (nc_inq_varid(grp, name.c_str(), &v) != NC_NOERR || variable_dimids(grp, v).size() != 2) continue;
      if (is_longitude(grp, v)) lon_var = v;
      if (is_latitude(grp, v)) lat_var = v;
    }
    if (lon_var < 0 || lat_var < 0) return;
    double worst = 0;
    for (const auto& [r, c] : std::array<std::pair<std::size_t, std::size_t>, 5>{
             {{0, 0}, {0, width_ - 1}, {height_ - 1, 0}, {height_ - 1, width_ - 1},
              {height_ / 2, width_ / 2}}}) {
      const std::size_t index[2] = {r, c};
      double lon = 0, lat = 0;
      if (nc_get_var1_double(grp, lon_var, index, &lon) != NC_NOERR ||
          nc_get_var1_double(grp, lat_var, index, &lat) != NC_NOERR) {
        return;
      }
      const auto g = GridProjection::for_this_thread(proj_).to_geographic(x_axis_[c], y_axis_[r]);
      const double dlon = std::fabs(std::remainder(g[0] - lon, 360.0));
      worst = std::max({worst, dlon, std::fabs(g[1] - lat)});
    }
    if (!(worst <= 1e-3)) {
      spdlog::warn("{}: grid mapping '{}' places samples up to {:.4f} degrees from the file's "
                   "own 2-D longitude/latitude; the grid mapping is used",
                   describe(), mapping_variable_, worst);
    }
  }

  std::filesystem::path path_;
  NcFile file_;
  int varid_ = -1;
  std::string name_;
  std::size_t ndims_ = 0, width_ = 0, height_ = 0;
  CfValueAttributes attributes_;
  double metres_per_unit_ = 1.0;
  std::vector<double> x_axis_, y_axis_;
  std::string proj_;  // the grid mapping's PROJ pipeline; empty: longitude/latitude axes
  std::string mapping_variable_, mapping_name_;
};

}  // namespace

std::unique_ptr<DemSource> open_netcdf_dem(const std::filesystem::path& path,
                                           const std::string& variable) {
  return std::make_unique<NetcdfDem>(path, variable);
}

}  // namespace strielad::geo
