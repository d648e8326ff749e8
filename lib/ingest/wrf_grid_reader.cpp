// SPDX-License-Identifier: Apache-2.0
#include "ingest/wrf_grid_reader.h"

#include <fmt/format.h>
#include <netcdf.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

#include "core/error.h"
#include "geo/cf_grid_mapping.h"
#include "geo/grid_projection.h"
#include "ingest/cf_attributes.h"
#include "ingest/netcdf_call.h"
#include "ingest/netcdf_file.h"
#include "ingest/wrf_times.h"

namespace strielad::ingest {
namespace {

constexpr double kMetresPerDegree = kWrfEarthRadius * std::numbers::pi / 180.0;

std::optional<int> dimension_id(int ncid, const char* name) {
  int id = -1;
  if (nc_inq_dimid(ncid, name, &id) != NC_NOERR) return std::nullopt;
  return id;
}

std::optional<double> global_number(int ncid, std::string_view name) {
  const auto v = numeric_attribute(ncid, NC_GLOBAL, name);
  if (v.empty()) return std::nullopt;
  return static_cast<double>(v.front());
}

double required_global(int ncid, std::string_view name, const std::string& file) {
  const auto v = global_number(ncid, name);
  if (!v || !std::isfinite(*v)) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: WRF global attribute {} is {}; the grid cannot be placed without it",
                     file, name, v ? "not finite" : "missing");
  }
  return *v;
}

std::size_t required_dimension(int ncid, const char* name, const std::string& file) {
  const auto id = dimension_id(ncid, name);
  if (!id) {
    throw make_error(ErrorCode::kInvalidInput, "{}: WRF file without dimension '{}'", file, name);
  }
  return dimension_length(ncid, *id);
}

// XLAT or XLONG: every step (or the one plane), ny x nx each.
struct LonLatPlanes {
  std::vector<double> values;
  std::size_t steps = 0;
};

LonLatPlanes read_mass_coordinate(int ncid, const char* name, std::size_t nx, std::size_t ny,
                                  const std::string& file) {
  int varid = -1;
  if (nc_inq_varid(ncid, name, &varid) != NC_NOERR) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: WRF file without '{}': the mass points cannot be checked", file, name);
  }
  LonLatPlanes p;
  p.values = read_all_as_double(ncid, varid, fmt::format("{}: variable '{}'", file, name));
  const std::size_t plane = nx * ny;
  if (plane == 0 || p.values.size() % plane != 0) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: variable '{}' holds {} values, not planes of {} x {} mass points",
                     file, name, p.values.size(), nx, ny);
  }
  p.steps = p.values.size() / plane;
  return p;
}

std::vector<std::string> read_times(int ncid, const std::string& file) {
  int varid = -1;
  if (nc_inq_varid(ncid, "Times", &varid) != NC_NOERR) return {};
  const auto dimids = variable_dimids(ncid, varid);
  if (dimids.size() != 2 || variable_type(ncid, varid) != NC_CHAR) {
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: variable 'Times' is not (Time, DateStrLen) characters", file);
  }
  const std::size_t steps = dimension_length(ncid, dimids[0]);
  const std::size_t width = dimension_length(ncid, dimids[1]);
  std::vector<char> text(steps * width);
  if (!text.empty()) {
    const std::size_t start[2] = {0, 0}, count[2] = {steps, width};
    nc_check(nc_get_vara_text(ncid, varid, start, count, text.data()),
             fmt::format("{}: variable 'Times'", file));
  }
  std::vector<std::string> out;
  for (std::size_t s = 0; s < steps; ++s) out.emplace_back(text.data() + s * width, width);
  return out;
}

Axis index_axis(const char* name, AxisKind kind, std::size_t n) {
  Axis a;
  a.name = name;
  a.kind = kind;
  for (std::size_t i = 0; i < n; ++i) a.values.push_back(static_cast<double>(i));
  return a;
}

// The CF-named mapping of a WRF projection, without its pipeline.
GridMapping wrf_mapping(int ncid, int map_proj, const std::string& file) {
  GridMapping m;
  m.variable = "MAP_PROJ";  // no variable: the global attributes
  auto& a = m.attributes;
  a["earth_radius"] = kWrfEarthRadius;
  a["false_easting"] = 0.0;
  a["false_northing"] = 0.0;
  a["wrf_map_proj"] = map_proj;
  const double truelat1 = required_global(ncid, "TRUELAT1", file);
  const double stand_lon = required_global(ncid, "STAND_LON", file);
  if (map_proj == 1) {
    const double truelat2 = global_number(ncid, "TRUELAT2").value_or(truelat1);
    m.name = "lambert_conformal_conic";
    // The origin's latitude only shifts y, which the mass points fix: any will do.
    const double origin = global_number(ncid, "MOAD_CEN_LAT").value_or(truelat1);
    a["standard_parallel"] = truelat1 == truelat2 ? nlohmann::json(truelat1)
                                                  : nlohmann::json::array({truelat1, truelat2});
    a["longitude_of_central_meridian"] = stand_lon;
    a["latitude_of_projection_origin"] = origin;
  } else if (map_proj == 2) {
    m.name = "polar_stereographic";
    a["latitude_of_projection_origin"] = truelat1 < 0 ? -90.0 : 90.0;
    a["straight_vertical_longitude_from_pole"] = stand_lon;
    a["standard_parallel"] = truelat1;
  } else {
    m.name = "mercator";
    a["longitude_of_projection_origin"] = stand_lon;
    a["standard_parallel"] = truelat1;
  }
  return m;
}

// Where the mass points are on the axes' plane, and how far XLAT/XLONG are from them.
struct Fit {
  double x0 = 0, y0 = 0;
  double worst = 0;
  std::size_t worst_i = 0, worst_j = 0, worst_step = 0;
};

class MassPointFitter {
 public:
  MassPointFitter(const geo::GridProjection* projection, std::size_t nx, std::size_t ny, double dx,
                  double dy)
      : projection_(projection), nx_(nx), ny_(ny), dx_(dx), dy_(dy) {}

  // (x, y) of a longitude/latitude on the axes' plane.
  std::array<double, 2> place(double lon, double lat, double near_lon) const {
    if (projection_ != nullptr) return projection_->to_axis(lon, lat);
    return {near_lon + std::remainder(lon - near_lon, 360.0), lat};
  }

  Fit fit(const LonLatPlanes& lon, const LonLatPlanes& lat) const {
    Fit f;
    const double near = lon.values[0];
    double sx = 0, sy = 0;
    for (std::size_t j = 0; j < ny_; ++j) {
      for (std::size_t i = 0; i < nx_; ++i) {
        const auto p = place(lon.values[j * nx_ + i], lat.values[j * nx_ + i], near);
        sx += p[0] - static_cast<double>(i) * dx_;
        sy += p[1] - static_cast<double>(j) * dy_;
      }
    }
    const double n = static_cast<double>(nx_ * ny_);
    f.x0 = sx / n;
    f.y0 = sy / n;
    for (std::size_t s = 0; s < lon.steps; ++s) {
      const std::size_t base = s * nx_ * ny_;
      for (std::size_t j = 0; j < ny_; ++j) {
        for (std::size_t i = 0; i < nx_; ++i) {
          const auto p = place(lon.values[base + j * nx_ + i], lat.values[base + j * nx_ + i], near);
          const double d = std::hypot(p[0] - (f.x0 + static_cast<double>(i) * dx_),
                                      p[1] - (f.y0 + static_cast<double>(j) * dy_));
          if (!(d <= f.worst)) {  // NaN (no position) is the worst of all
            f.worst = std::isnan(d) ? std::numeric_limits<double>::infinity() : d;
            f.worst_i = i;
            f.worst_j = j;
            f.worst_step = s;
          }
        }
      }
    }
    return f;
  }

 private:
  const geo::GridProjection* projection_;
  std::size_t nx_, ny_;
  double dx_, dy_;
};

}  // namespace

bool is_wrf_file(int ncid) {
  if (text_attribute_or_empty(ncid, NC_GLOBAL, "TITLE").find("OUTPUT FROM WRF") !=
      std::string::npos) {
    return true;
  }
  return dimension_id(ncid, "west_east") && dimension_id(ncid, "south_north") &&
         dimension_id(ncid, "bottom_top") && has_attribute(ncid, NC_GLOBAL, "MAP_PROJ");
}

WrfLayout read_wrf_layout(int ncid, const std::string& file) {
  const std::size_t nx = required_dimension(ncid, "west_east", file);
  const std::size_t ny = required_dimension(ncid, "south_north", file);
  const std::size_t nz = required_dimension(ncid, "bottom_top", file);
  const int map_proj = static_cast<int>(required_global(ncid, "MAP_PROJ", file));
  const double dx = required_global(ncid, "DX", file), dy = required_global(ncid, "DY", file);
  if (!(dx > 0) || !(dy > 0)) {
    throw make_error(ErrorCode::kInvalidInput, "{}: WRF global attributes DX {} and DY {} must be "
                     "positive", file, dx, dy);
  }

  WrfLayout out;
  out.x = index_axis("west_east", AxisKind::kProjectionX, nx);
  out.y = index_axis("south_north", AxisKind::kProjectionY, ny);
  out.z = index_axis("bottom_top", AxisKind::kModelLevel, nz);
  out.z.long_name = "WRF mass level index, 0 at the ground (PH + PHB give the heights)";
  out.z.positive = "up";

  double step_x = dx, step_y = dy;
  std::optional<geo::GridProjection> projection;
  if (map_proj == 1 || map_proj == 2 || map_proj == 3) {
    out.x.units = out.y.units = "m";
    out.x.standard_name = "projection_x_coordinate";
    out.y.standard_name = "projection_y_coordinate";
    GridMapping m = wrf_mapping(ncid, map_proj, file);
    m.proj = geo::cf_grid_mapping_proj(m, out.x, out.y, file);
    projection.emplace(m.proj);
    out.mapping = std::move(m);
  } else if (map_proj == 6) {
    const double pole_lat = global_number(ncid, "POLE_LAT").value_or(90.0);
    const double pole_lon = global_number(ncid, "POLE_LON").value_or(0.0);
    if (pole_lat != 90.0 || (pole_lon != 0.0 && pole_lon != 180.0)) {
      throw make_error(ErrorCode::kUnsupported,
                       "{}: WRF MAP_PROJ 6 with POLE_LAT {} and POLE_LON {} is a rotated "
                       "latitude/longitude grid, which is not converted yet (only POLE_LAT 90 "
                       "is); remap it first",
                       file, pole_lat, pole_lon);
    }
    out.x.kind = AxisKind::kLongitude;
    out.y.kind = AxisKind::kLatitude;
    out.x.units = "degrees_east";
    out.y.units = "degrees_north";
    out.x.standard_name = "longitude";
    out.y.standard_name = "latitude";
    step_x = dx / kMetresPerDegree;
    step_y = dy / kMetresPerDegree;
  } else {
    throw make_error(ErrorCode::kUnsupported,
                     "{}: WRF MAP_PROJ {} is not converted (1 Lambert conformal, 2 polar "
                     "stereographic, 3 Mercator and 6 latitude/longitude are)",
                     file, map_proj);
  }

  const LonLatPlanes lon = read_mass_coordinate(ncid, "XLONG", nx, ny, file);
  const LonLatPlanes lat = read_mass_coordinate(ncid, "XLAT", nx, ny, file);
  if (lon.steps != lat.steps) {
    throw make_error(ErrorCode::kInvalidInput, "{}: XLONG has {} steps but XLAT {}", file,
                     lon.steps, lat.steps);
  }
  const MassPointFitter fitter(projection ? &*projection : nullptr, nx, ny, step_x, step_y);
  const Fit f = fitter.fit(lon, lat);
  const double tolerance = projection ? std::max(0.5, 1e-3 * std::min(dx, dy))
                                      : 1e-3 * std::min(step_x, step_y);
  const std::string unit = projection ? "m" : "degrees";
  if (!(f.worst <= tolerance)) {
    const std::size_t at = (f.worst_step * ny + f.worst_j) * nx + f.worst_i;
    throw make_error(ErrorCode::kInvalidInput,
                     "{}: XLAT/XLONG of mass point (west_east {}, south_north {}) at step {} "
                     "({}, {}) is {:.6g} {} from where MAP_PROJ {} with DX {} and DY {} puts it "
                     "(tolerance {:.3g} {}); the grid is not the one the global attributes "
                     "describe (a moving nest, edited coordinates or inconsistent attributes)",
                     file, f.worst_i, f.worst_j, f.worst_step, lat.values[at], lon.values[at],
                     f.worst, unit, map_proj, dx, dy, tolerance, unit);
  }
  for (std::size_t i = 0; i < nx; ++i) out.x.values[i] = f.x0 + static_cast<double>(i) * step_x;
  for (std::size_t j = 0; j < ny; ++j) out.y.values[j] = f.y0 + static_cast<double>(j) * step_y;
  out.max_deviation = f.worst;

  const std::vector<std::string> times = read_times(ncid, file);
  if (dimension_id(ncid, "Time")) {
    if (times.empty() && required_dimension(ncid, "Time", file) > 0) {
      throw make_error(ErrorCode::kInvalidInput, "{}: WRF file without 'Times'", file);
    }
    out.time = wrf_time_coordinate(times, file);
  }
  return out;
}

}  // namespace strielad::ingest
