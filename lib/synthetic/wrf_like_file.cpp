// SPDX-License-Identifier: Apache-2.0
#include "synthetic/wrf_like_file.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <functional>
#include <numbers>
#include <span>

#include "core/error.h"
#include "geo/cf_calendar.h"
#include "synthetic/atmosphere_profiles.h"
#include "synthetic/hash_noise.h"
#include "synthetic/model_atmosphere.h"
#include "synthetic/model_levels.h"
#include "synthetic/model_netcdf_file.h"
#include "synthetic/sample_grid.h"
#include "synthetic/sample_terrain.h"
#include "synthetic/wrf_grid.h"

namespace strielad::synthetic {
namespace {

using Type = ModelNetcdfFile::Type;
using Format = ModelNetcdfFile::Format;

constexpr geo::CfDate kStartDay{2013, 4, 26};
constexpr std::int64_t kStartSecondOfDay = 12 * 3600;
constexpr const char* kXtimeUnits = "minutes since 2013-04-26 12:00:00";
constexpr double kKappa = 2.0 / 7.0;                 // R / cp of dry air, as WRF
constexpr double kReferencePressure = 100000.0;     // Pa, of the potential temperature
constexpr std::uint64_t kSaltWrfGeopotential = 43;  // phase of the PH wave
constexpr double kPhAmplitude = 20.0;                // m, of (PH / g) at the top

// Levels counted from the ground as WRF does: w level k at height wa[k] + wb[k] * HGT
// (the hybrid height levels of model_levels.h, bottom up), eta of the standard
// atmosphere at the nominal heights.
struct WrfLevels {
  std::vector<double> wa, wb, znw, znu;
  double p_top = 0;
};

WrfLevels wrf_levels(std::size_t nz) {
  const HybridHeightLevels h = hybrid_height_levels(nz);
  WrfLevels l;
  l.wa.resize(nz + 1);
  l.wb.resize(nz + 1);
  l.znw.resize(nz + 1);
  l.znu.resize(nz);
  l.p_top = column_pressure(kModelTop, kSurfacePressure, 0.0);
  for (std::size_t k = 0; k <= nz; ++k) {
    l.wa[k] = h.half_a[nz - k];
    l.wb[k] = h.half_b[nz - k];
    l.znw[k] = (column_pressure(l.wa[k], kSurfacePressure, 0.0) - l.p_top) /
               (kSurfacePressure - l.p_top);
  }
  l.znw.front() = 1.0;
  l.znw.back() = 0.0;
  for (std::size_t k = 0; k < nz; ++k) l.znu[k] = 0.5 * (l.znw[k] + l.znw[k + 1]);
  return l;
}

struct WrfDims {
  int time = -1, date = -1, we = -1, sn = -1, bt = -1, we_s = -1, sn_s = -1, bt_s = -1;
};

struct WrfIds {
  int times = -1, xtime = -1, xlat = -1, xlong = -1, xlat_u = -1, xlong_u = -1, xlat_v = -1,
      xlong_v = -1, znu = -1, znw = -1, p_top = -1, hgt = -1, cosalpha = -1, sinalpha = -1;
  int u = -1, v = -1, w = -1, ph = -1, phb = -1, t = -1, p = -1, pb = -1, qvapor = -1,
      qcloud = -1;
};

// One NC_FLOAT variable with WRF's attributes.
struct WrfVariable {
  const char* name;
  std::initializer_list<int> dims;
  const char* memory_order;
  const char* description;
  const char* units;
  const char* stagger;
  const char* coordinates;  // nullptr: none
};

// Defines WRF variables; in NetCDF-4 files chunked by horizontal planes and deflated.
class WrfDefiner {
 public:
  WrfDefiner(ModelNetcdfFile& f, bool chunked, int deflate) : f_(f), chunked_(chunked), deflate_(deflate) {}

  int dimension(const char* name, std::size_t length) {
    const int id = f_.dimension(name, length);
    if (lengths_.size() <= static_cast<std::size_t>(id)) lengths_.resize(static_cast<std::size_t>(id) + 1);
    lengths_[static_cast<std::size_t>(id)] = length == 0 ? 1 : length;
    return id;
  }

  int variable(const WrfVariable& v) {
    const int id = f_.variable(v.name, Type::kFloat, v.dims);
    if (chunked_ && v.dims.size() >= 3) {
      std::vector<std::size_t> plane;
      std::size_t axis = 0;
      for (const int d : v.dims) {
        plane.push_back(axis + 2 >= v.dims.size() ? lengths_[static_cast<std::size_t>(d)] : 1);
        ++axis;
      }
      f_.chunk_by_plane(id, plane, deflate_);
    }
    f_.integer(id, "FieldType", 104);
    f_.text(id, "MemoryOrder", v.memory_order);
    f_.text(id, "description", v.description);
    f_.text(id, "units", v.units);
    f_.text(id, "stagger", v.stagger);
    if (v.coordinates != nullptr) f_.text(id, "coordinates", v.coordinates);
    return id;
  }

 private:
  ModelNetcdfFile& f_;
  bool chunked_;
  int deflate_;
  std::vector<std::size_t> lengths_;
};

constexpr const char* kMass = "XLONG XLAT XTIME";
constexpr const char* kUPoints = "XLONG_U XLAT_U XTIME";
constexpr const char* kVPoints = "XLONG_V XLAT_V XTIME";

WrfIds define_file(ModelNetcdfFile& f, const SampleSpec& spec, const WrfGrid& grid,
                   bool netcdf4) {
  WrfDefiner def(f, netcdf4, spec.deflate);
  const Dims3& d = spec.dims;
  WrfDims n;
  n.time = def.dimension("Time", 0);
  n.date = def.dimension("DateStrLen", 19);
  n.we = def.dimension("west_east", d.x);
  n.sn = def.dimension("south_north", d.y);
  n.bt = def.dimension("bottom_top", d.z);
  n.we_s = def.dimension("west_east_stag", d.x + 1);
  n.sn_s = def.dimension("south_north_stag", d.y + 1);
  n.bt_s = def.dimension("bottom_top_stag", d.z + 1);

  WrfIds ids;
  ids.times = f.variable("Times", Type::kChar, {n.time, n.date});
  const char* lat_text = "LATITUDE, SOUTH IS NEGATIVE";
  const char* lon_text = "LONGITUDE, WEST IS NEGATIVE";
  ids.xlat = def.variable({"XLAT", {n.time, n.sn, n.we}, "XY ", lat_text, "degree_north", "", "XLONG XLAT"});
  ids.xlong = def.variable({"XLONG", {n.time, n.sn, n.we}, "XY ", lon_text, "degree_east", "", "XLONG XLAT"});
  ids.znu = def.variable({"ZNU", {n.time, n.bt}, "Z  ", "eta values on half (mass) levels", "", "", nullptr});
  ids.znw = def.variable({"ZNW", {n.time, n.bt_s}, "Z  ", "eta values on full (w) levels", "", "Z", nullptr});
  ids.u = def.variable({"U", {n.time, n.bt, n.sn, n.we_s}, "XYZ", "x-wind component", "m s-1", "X", kUPoints});
  ids.v = def.variable({"V", {n.time, n.bt, n.sn_s, n.we}, "XYZ", "y-wind component", "m s-1", "Y", kVPoints});
  ids.w = def.variable({"W", {n.time, n.bt_s, n.sn, n.we}, "XYZ", "z-wind component", "m s-1", "Z", kMass});
  ids.ph = def.variable({"PH", {n.time, n.bt_s, n.sn, n.we}, "XYZ", "perturbation geopotential", "m2 s-2", "Z", kMass});
  ids.phb = def.variable({"PHB", {n.time, n.bt_s, n.sn, n.we}, "XYZ", "base-state geopotential", "m2 s-2", "Z", kMass});
  ids.t = def.variable({"T", {n.time, n.bt, n.sn, n.we}, "XYZ", "perturbation potential temperature theta-t0", "K", "", kMass});
  ids.p = def.variable({"P", {n.time, n.bt, n.sn, n.we}, "XYZ", "perturbation pressure", "Pa", "", kMass});
  ids.pb = def.variable({"PB", {n.time, n.bt, n.sn, n.we}, "XYZ", "BASE STATE PRESSURE", "Pa", "", kMass});
  ids.p_top = def.variable({"P_TOP", {n.time}, "0  ", "PRESSURE TOP OF THE MODEL", "Pa", "", nullptr});
  ids.qvapor = def.variable({"QVAPOR", {n.time, n.bt, n.sn, n.we}, "XYZ", "Water vapor mixing ratio", "kg kg-1", "", kMass});
  ids.qcloud = def.variable({"QCLOUD", {n.time, n.bt, n.sn, n.we}, "XYZ", "Cloud water mixing ratio", "kg kg-1", "", kMass});
  ids.hgt = def.variable({"HGT", {n.time, n.sn, n.we}, "XY ", "Terrain Height", "m", "", kMass});
  ids.cosalpha = def.variable({"COSALPHA", {n.time, n.sn, n.we}, "XY ", "Local cosine of map rotation", "", "", kMass});
  ids.sinalpha = def.variable({"SINALPHA", {n.time, n.sn, n.we}, "XY ", "Local sine of map rotation", "", "", kMass});
  ids.xlat_u = def.variable({"XLAT_U", {n.time, n.sn, n.we_s}, "XY ", lat_text, "degree_north", "X", "XLONG_U XLAT_U"});
  ids.xlong_u = def.variable({"XLONG_U", {n.time, n.sn, n.we_s}, "XY ", lon_text, "degree_east", "X", "XLONG_U XLAT_U"});
  ids.xlat_v = def.variable({"XLAT_V", {n.time, n.sn_s, n.we}, "XY ", lat_text, "degree_north", "Y", "XLONG_V XLAT_V"});
  ids.xlong_v = def.variable({"XLONG_V", {n.time, n.sn_s, n.we}, "XY ", lon_text, "degree_east", "Y", "XLONG_V XLAT_V"});
  ids.xtime = def.variable({"XTIME", {n.time}, "0  ", kXtimeUnits, kXtimeUnits, "", nullptr});

  constexpr int g = ModelNetcdfFile::kGlobal;
  const auto fl = [](double v) { return static_cast<float>(v); };
  f.text(g, "TITLE", " OUTPUT FROM WRF V4.4 MODEL");
  f.text(g, "START_DATE", kWrfStartDate);
  f.text(g, "SIMULATION_START_DATE", kWrfStartDate);
  f.integer(g, "WEST-EAST_GRID_DIMENSION", static_cast<int>(d.x + 1));
  f.integer(g, "SOUTH-NORTH_GRID_DIMENSION", static_cast<int>(d.y + 1));
  f.integer(g, "BOTTOM-TOP_GRID_DIMENSION", static_cast<int>(d.z + 1));
  f.float_number(g, "DX", fl(grid.dx));
  f.float_number(g, "DY", fl(grid.dy));
  f.text(g, "GRIDTYPE", "C");
  f.float_number(g, "CEN_LAT", fl(grid.cen_lat));
  f.float_number(g, "CEN_LON", fl(grid.cen_lon));
  f.float_number(g, "TRUELAT1", fl(kWrfTrueLat1));
  f.float_number(g, "TRUELAT2", fl(kWrfTrueLat2));
  f.float_number(g, "MOAD_CEN_LAT", fl(grid.cen_lat));
  f.float_number(g, "STAND_LON", fl(grid.cen_lon));
  f.float_number(g, "POLE_LAT", 90.0f);
  f.float_number(g, "POLE_LON", 0.0f);
  f.integer(g, "MAP_PROJ", 1);
  f.text(g, "MAP_PROJ_CHAR", "Lambert Conformal");
  f.text(g, "STRIELAD_SOURCE",
         fmt::format("strielad-sample --model wrf, seed {}: deterministic synthetic fields over "
                     "the synthetic sample terrain; not model output",
                     spec.seed));
  return ids;
}

// The value at the staggered points of a (ny x nx) mass field: the mean of the two
// mass neighbours, the nearest one on the boundary.
std::vector<double> to_u_points(std::span<const double> mass, std::size_t nx, std::size_t ny) {
  std::vector<double> out((nx + 1) * ny);
  for (std::size_t j = 0; j < ny; ++j) {
    const double* row = &mass[j * nx];
    for (std::size_t i = 0; i <= nx; ++i) {
      out[j * (nx + 1) + i] = i == 0 ? row[0] : i == nx ? row[nx - 1] : 0.5 * (row[i - 1] + row[i]);
    }
  }
  return out;
}

std::vector<double> to_v_points(std::span<const double> mass, std::size_t nx, std::size_t ny) {
  std::vector<double> out(nx * (ny + 1));
  for (std::size_t j = 0; j <= ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      out[j * nx + i] = j == 0    ? mass[i]
                        : j == ny ? mass[(ny - 1) * nx + i]
                                  : 0.5 * (mass[(j - 1) * nx + i] + mass[j * nx + i]);
    }
  }
  return out;
}

std::vector<float> to_floats(std::span<const double> v) {
  return std::vector<float>(v.begin(), v.end());
}

// A SampleGrid whose local plane is the Lambert projection's (km from the centre),
// shifted by (di, dj) cells: the atmosphere's fields at the WRF points.
SampleGrid atmosphere_grid(const WrfGrid& g, std::size_t nx, std::size_t ny, std::size_t nz,
                           double di, double dj) {
  SampleGrid grid(Dims3{nx, ny, nz});
  for (std::size_t i = 0; i < nx; ++i) grid.x_km[i] = g.x_at(static_cast<double>(i) + di) / 1000.0;
  for (std::size_t j = 0; j < ny; ++j) grid.y_km[j] = g.y_at(static_cast<double>(j) + dj) / 1000.0;
  return grid;
}

// What every file of one dataset shares.
struct WrfContext {
  const SampleSpec& spec;
  const WrfGrid& grid;
  const WrfLevels& levels;
  const SampleGrid &mass_grid, &u_grid, &v_grid;
  std::vector<double> hgt, hgt_u, hgt_v;        // terrain at the mass, U and V points
  std::vector<double> cos_m, sin_m, cos_u, sin_u, cos_v, sin_v;  // map rotation
  double ph_phase = 0;
};

// (PH / g) of column c at time t: a wave of kPhAmplitude at the top, zero at the ground.
std::vector<double> ph_amplitude(const WrfContext& ctx, double seconds) {
  const std::size_t nx = ctx.grid.nx, ny = ctx.grid.ny;
  std::vector<double> a(nx * ny);
  const double t_km = seconds / 1000.0;
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const double x = ctx.grid.x[i] / 1000.0, y = ctx.grid.y[j] / 1000.0;
      a[j * nx + i] = kPhAmplitude * std::sin(2 * std::numbers::pi * (x - 10.0 * t_km) / 600.0 +
                                              ctx.ph_phase) *
                      std::cos(2 * std::numbers::pi * y / 900.0);
    }
  }
  return a;
}

void write_step(ModelNetcdfFile& f, const WrfIds& ids, const WrfContext& ctx, std::size_t s,
                double seconds, const std::function<void()>& level_done) {
  const std::size_t nx = ctx.grid.nx, ny = ctx.grid.ny, nz = ctx.spec.dims.z, n = nx * ny;
  const WrfLevels& lv = ctx.levels;
  const auto put2 = [&](int var, std::size_t rows, std::size_t cols, std::span<const double> v) {
    const std::array<std::size_t, 3> start{s, 0, 0}, count{1, rows, cols};
    f.put(var, start, count, std::span<const float>(to_floats(v)));
  };
  const auto put3 = [&](int var, std::size_t k, std::size_t rows, std::size_t cols,
                        std::span<const float> v) {
    const std::array<std::size_t, 4> start{s, k, 0, 0}, count{1, 1, rows, cols};
    f.put(var, start, count, v);
  };
  const auto put1 = [&](int var, std::span<const double> v) {
    const std::array<std::size_t, 2> start{s, 0}, count{1, v.size()};
    f.put(var, start, count, std::span<const float>(to_floats(v)));
  };

  const std::string date = wrf_date_string(seconds);
  const std::array<std::size_t, 2> date_start{s, 0}, date_count{1, date.size()};
  f.put_text(ids.times, date_start, date_count, date);
  const std::array<std::size_t, 1> t_start{s}, t_count{1};
  const std::array<float, 1> xtime{static_cast<float>(seconds / 60.0)};
  f.put(ids.xtime, t_start, t_count, xtime);
  const std::array<float, 1> p_top{static_cast<float>(lv.p_top)};
  f.put(ids.p_top, t_start, t_count, p_top);
  put2(ids.xlat, ny, nx, ctx.grid.lat);
  put2(ids.xlong, ny, nx, ctx.grid.lon);
  put2(ids.xlat_u, ny, nx + 1, ctx.grid.lat_u);
  put2(ids.xlong_u, ny, nx + 1, ctx.grid.lon_u);
  put2(ids.xlat_v, ny + 1, nx, ctx.grid.lat_v);
  put2(ids.xlong_v, ny + 1, nx, ctx.grid.lon_v);
  put2(ids.hgt, ny, nx, ctx.hgt);
  put2(ids.cosalpha, ny, nx, ctx.cos_m);
  put2(ids.sinalpha, ny, nx, ctx.sin_m);
  put1(ids.znu, lv.znu);
  put1(ids.znw, lv.znw);

  const std::vector<float> hgt_f = to_floats(ctx.hgt), hgt_u_f = to_floats(ctx.hgt_u),
                           hgt_v_f = to_floats(ctx.hgt_v);
  const ModelAtmosphere mass(ctx.mass_grid, hgt_f, ctx.spec.seed, seconds);
  const ModelAtmosphere at_u(ctx.u_grid, hgt_u_f, ctx.spec.seed, seconds);
  const ModelAtmosphere at_v(ctx.v_grid, hgt_v_f, ctx.spec.seed, seconds);
  const std::vector<double> ph = ph_amplitude(ctx, seconds);

  // Heights (m) of w level k in every column, and the geopotentials there.
  const auto w_level = [&](std::size_t k, std::vector<double>& z) {
    std::vector<float> phb(n), php(n);
    for (std::size_t c = 0; c < n; ++c) {
      const double base = lv.wa[k] + lv.wb[k] * ctx.hgt[c];
      const double pert = ph[c] * (1.0 - lv.znw[k]);
      phb[c] = static_cast<float>(kWrfGravity * base);
      php[c] = static_cast<float>(kWrfGravity * pert);
      z[c] = base + pert;
    }
    put3(ids.phb, k, ny, nx, phb);
    put3(ids.ph, k, ny, nx, php);
    std::vector<float> w(n);
    mass.fill(ModelField::kUpward, z, w);
    put3(ids.w, k, ny, nx, w);
  };

  std::vector<double> z_below(n), z_above(n), z_mass(n);
  std::vector<float> temperature(n), pressure(n), values(n);
  w_level(0, z_below);
  for (std::size_t k = 0; k < nz; ++k) {
    w_level(k + 1, z_above);
    for (std::size_t c = 0; c < n; ++c) z_mass[c] = 0.5 * (z_below[c] + z_above[c]);

    mass.fill(ModelField::kTemperature, z_mass, temperature);
    mass.fill(ModelField::kPressure, z_mass, pressure);
    std::vector<float> theta(n), p_pert(n), p_base(n);
    for (std::size_t c = 0; c < n; ++c) {
      const double pb = column_pressure(z_mass[c], kSurfacePressure, 0.0);
      const double p = pressure[c];
      theta[c] = static_cast<float>(temperature[c] * std::pow(kReferencePressure / p, kKappa) -
                                    kWrfThetaBase);
      p_base[c] = static_cast<float>(pb);
      p_pert[c] = static_cast<float>(p - pb);
    }
    put3(ids.t, k, ny, nx, theta);
    put3(ids.p, k, ny, nx, p_pert);
    put3(ids.pb, k, ny, nx, p_base);
    mass.fill(ModelField::kSpecificHumidity, z_mass, values);
    for (float& q : values) q = q / (1.0f - q);
    put3(ids.qvapor, k, ny, nx, values);
    mass.fill(ModelField::kCloudWater, z_mass, values);
    put3(ids.qcloud, k, ny, nx, values);

    // Grid-relative wind: U = u cos + v sin, V = v cos - u sin.
    const auto staggered_wind = [&](const ModelAtmosphere& atmosphere, std::vector<double> z,
                                    const std::vector<double>& cos_a,
                                    const std::vector<double>& sin_a, bool along_x, int var,
                                    std::size_t rows, std::size_t cols) {
      std::vector<float> u(z.size()), v(z.size()), out(z.size());
      atmosphere.fill(ModelField::kEastward, z, u);
      atmosphere.fill(ModelField::kNorthward, z, v);
      for (std::size_t c = 0; c < z.size(); ++c) {
        out[c] = static_cast<float>(along_x ? u[c] * cos_a[c] + v[c] * sin_a[c]
                                            : v[c] * cos_a[c] - u[c] * sin_a[c]);
      }
      put3(var, k, rows, cols, out);
    };
    staggered_wind(at_u, to_u_points(z_mass, nx, ny), ctx.cos_u, ctx.sin_u, true, ids.u, ny, nx + 1);
    staggered_wind(at_v, to_v_points(z_mass, nx, ny), ctx.cos_v, ctx.sin_v, false, ids.v, ny + 1, nx);
    for (int i = 0; i < 10; ++i) level_done();
    std::swap(z_below, z_above);
  }
}

SampleFile write_wrf_file(const std::filesystem::path& path, const WrfContext& ctx,
                          std::span<const double> times, const std::function<void()>& level_done) {
  const bool netcdf4 = ctx.spec.deflate > 0;
  ModelNetcdfFile f(path, netcdf4 ? Format::kNetcdf4 : Format::kClassic64BitOffset);
  const WrfIds ids = define_file(f, ctx.spec, ctx.grid, netcdf4);
  f.end_define();
  for (std::size_t s = 0; s < times.size(); ++s) write_step(f, ids, ctx, s, times[s], level_done);
  const std::uint64_t bytes = f.commit();
  return SampleFile{path, bytes};
}

void rotations(const WrfGrid& g, const std::vector<double>& lon, std::vector<double>& cos_a,
               std::vector<double>& sin_a) {
  cos_a.resize(lon.size());
  sin_a.resize(lon.size());
  for (std::size_t p = 0; p < lon.size(); ++p) {
    const auto [c, s] = wrf_rotation(g, lon[p]);
    cos_a[p] = c;
    sin_a[p] = s;
  }
}

}  // namespace

std::string wrf_date_string(double seconds) {
  const std::int64_t total = kStartSecondOfDay + std::llround(seconds);
  const std::int64_t days = total >= 0 ? total / 86400 : -((-total + 86399) / 86400);
  const std::int64_t in_day = total - days * 86400;
  const geo::CfDate date = geo::cf_date_of_day(
      geo::CfCalendar::kProlepticGregorian,
      geo::cf_day_number(geo::CfCalendar::kProlepticGregorian, kStartDay) + days);
  return fmt::format("{:04d}-{:02d}-{:02d}_{:02d}:{:02d}:{:02d}", date.year, date.month, date.day,
                     in_day / 3600, in_day / 60 % 60, in_day % 60);
}

std::vector<std::string> wrf_sample_variable_names() {
  return {"U", "V", "W", "PH", "PHB", "T", "P", "PB", "QVAPOR", "QCLOUD"};
}

std::vector<std::string> wrf_sample_file_names(const SampleSpec& spec) {
  std::vector<std::string> names;
  const std::size_t files = spec.file_per_step ? spec.steps : 1;
  for (std::size_t s = 0; s < files; ++s) {
    names.push_back("wrfout_d01_" + wrf_date_string(static_cast<double>(s) * spec.step_seconds));
  }
  return names;
}

SampleResult write_wrf_like_dataset(const SampleSpec& spec, const std::filesystem::path& out_dir,
                                    SampleProgress progress) {
  validate_sample_spec(spec);
  const std::vector<std::string> names = wrf_sample_file_names(spec);
  prepare_sample_directory(out_dir);

  const std::size_t nx = spec.dims.x, ny = spec.dims.y, nz = spec.dims.z;
  const WrfGrid grid = wrf_grid(nx, ny);
  const WrfLevels levels = wrf_levels(nz);
  const SampleGrid mass_grid = atmosphere_grid(grid, nx, ny, nz, 0.0, 0.0);
  const SampleGrid u_grid = atmosphere_grid(grid, nx + 1, ny, nz, -0.5, 0.0);
  const SampleGrid v_grid = atmosphere_grid(grid, nx, ny + 1, nz, 0.0, -0.5);
  WrfContext ctx{spec, grid, levels, mass_grid, u_grid, v_grid, {}, {}, {}, {}, {}, {}, {}, {}, {}, 0.0};
  const std::vector<float> terrain = sample_terrain_heights_at(grid.lon, grid.lat, spec.seed);
  ctx.hgt.assign(terrain.begin(), terrain.end());
  ctx.hgt_u = to_u_points(ctx.hgt, nx, ny);
  ctx.hgt_v = to_v_points(ctx.hgt, nx, ny);
  rotations(grid, grid.lon, ctx.cos_m, ctx.sin_m);
  rotations(grid, grid.lon_u, ctx.cos_u, ctx.sin_u);
  rotations(grid, grid.lon_v, ctx.cos_v, ctx.sin_v);
  ctx.ph_phase = 2 * std::numbers::pi * unit_hash(noise_key(spec.seed, kSaltWrfGeopotential), 0);

  return write_step_files(
      spec, out_dir, names, static_cast<std::uint64_t>(wrf_sample_variable_names().size()) * nz,
      [&](const std::filesystem::path& path, std::span<const double> times,
          const std::function<void()>& level_done) {
        return write_wrf_file(path, ctx, times, level_done);
      },
      progress);
}

}  // namespace strielad::synthetic
