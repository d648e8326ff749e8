// SPDX-License-Identifier: Apache-2.0
#include "synthetic/model_like_files.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <functional>
#include <span>

#include "core/error.h"
#include "geo/cf_calendar.h"
#include "synthetic/curvilinear_like_file.h"
#include "synthetic/model_atmosphere.h"
#include "synthetic/model_levels.h"
#include "synthetic/model_netcdf_file.h"
#include "synthetic/model_variables.h"
#include "synthetic/sample_grid.h"
#include "synthetic/sample_terrain.h"
#include "synthetic/sample_writer.h"
#include "synthetic/wrf_like_file.h"

namespace strielad::synthetic {
namespace {

using Type = ModelNetcdfFile::Type;


constexpr std::array<ModelVariable, 4> kSigmaPressureVariables{{
    {"t", ModelField::kTemperature, "K", "air_temperature", "Temperature"},
    {"q", ModelField::kSpecificHumidity, "kg kg-1", "specific_humidity", "Specific humidity"},
    {"u", ModelField::kEastward, "m s-1", "eastward_wind", "U component of wind"},
    {"v", ModelField::kNorthward, "m s-1", "northward_wind", "V component of wind"},
}};

// The reference time of every sample (kSampleTimeUnits): 2013-04-26 12:00 UTC.
constexpr geo::CfDate kReferenceDate{2013, 4, 26};
constexpr double kReferenceSecondOfDay = 12 * 3600.0;
constexpr const char* kIconTimeUnits = "day as %Y%m%d.%f";

std::span<const ModelVariable> model_variables(SampleModel model) {
  if (model == SampleModel::kSigmaPressure) return kSigmaPressureVariables;
  return kIconVariables;
}

const char* file_prefix(SampleModel model) {
  switch (model) {
    case SampleModel::kIcon:
      return "icon";
    case SampleModel::kIconCf:
      return "icon_cf";
    case SampleModel::kSigmaPressure:
      return "sigma_pressure";
    case SampleModel::kWrf:
      return "wrfout";
    case SampleModel::kCurvilinear:
      return "curvilinear";
    case SampleModel::kSample:
      break;
  }
  throw make_error(ErrorCode::kInvalidArgument,
                   "model sample: the default sample is written by write_sample_dataset");
}

// ICON's absolute time: YYYYMMDD plus the fraction of the day, e.g. 20130426.5.
double icon_day_value(double seconds) {
  const double since_midnight = kReferenceSecondOfDay + seconds;
  const double whole_days = std::floor(since_midnight / 86400.0);
  const geo::CfDate date = geo::cf_date_of_day(
      geo::CfCalendar::kProlepticGregorian,
      geo::cf_day_number(geo::CfCalendar::kProlepticGregorian, kReferenceDate) +
          static_cast<std::int64_t>(whole_days));
  const double fraction = (since_midnight - whole_days * 86400.0) / 86400.0;
  return static_cast<double>(date.year * 10000 + date.month * 100 + date.day) + fraction;
}

// What one file holds and where its variables are.
struct FileIds {
  int time = -1, lat = -1, lon = -1, level = -1;
  int z_ifc = -1, z_mc = -1, surface = -1, b = -1, hyam = -1, hybm = -1, ps = -1;
  int height_2 = -1;
  std::vector<int> variables;  // model_variables() order
};

void put_axis_attributes(ModelNetcdfFile& f, int var, const char* standard_name,
                         const char* long_name, const char* units, const char* axis) {
  if (standard_name != nullptr) f.text(var, "standard_name", standard_name);
  f.text(var, "long_name", long_name);
  f.text(var, "units", units);
  f.text(var, "axis", axis);
}

// The level index axis of ICON: 1 .. n from the top.
int define_icon_index_axis(ModelNetcdfFile& f, const char* name, int dim, const char* long_name) {
  const int var = f.variable(name, Type::kDouble, {dim});
  put_axis_attributes(f, var, nullptr, long_name, "1", "Z");
  f.text(var, "positive", "down");
  return var;
}

int define_surface(ModelNetcdfFile& f, const char* name, int dim_lat, int dim_lon,
                   const char* long_name) {
  const int var = f.variable(name, Type::kFloat, {dim_lat, dim_lon});
  f.text(var, "standard_name", "surface_altitude");
  f.text(var, "long_name", long_name);
  f.text(var, "units", "m");
  return var;
}

int define_height_field(ModelNetcdfFile& f, const char* name, int dim_level, int dim_lat,
                        int dim_lon, const char* long_name, const std::array<std::size_t, 3>& chunk,
                        int deflate) {
  const int var = f.variable(name, Type::kFloat, {dim_level, dim_lat, dim_lon});
  f.chunk_by_plane(var, chunk, deflate);
  f.text(var, "standard_name", "altitude");
  f.text(var, "long_name", long_name);
  f.text(var, "units", "m");
  return var;
}

FileIds define_file(ModelNetcdfFile& f, SampleModel model, const SampleSpec& spec,
                    const ModelSampleOptions& options) {
  const Dims3& d = spec.dims;
  const bool icon = model == SampleModel::kIcon;
  FileIds ids;
  const int dim_time = f.dimension("time", 0);
  const int dim_level = f.dimension(icon ? "height" : "lev", d.z);
  const int dim_half = icon ? f.dimension("height_2", d.z + 1) : -1;
  const int dim_lat = f.dimension("lat", d.y);
  const int dim_lon = f.dimension("lon", d.x);

  ids.time = f.variable("time", Type::kDouble, {dim_time});
  put_axis_attributes(f, ids.time, "time", "time", icon ? kIconTimeUnits : kSampleTimeUnits, "T");
  f.text(ids.time, "calendar", "proleptic_gregorian");
  ids.lat = f.variable("lat", Type::kDouble, {dim_lat});
  put_axis_attributes(f, ids.lat, "latitude", "latitude", "degrees_north", "Y");
  ids.lon = f.variable("lon", Type::kDouble, {dim_lon});
  put_axis_attributes(f, ids.lon, "longitude", "longitude", "degrees_east", "X");

  const std::array<std::size_t, 3> plane{1, d.y, d.x};
  switch (model) {
    case SampleModel::kIcon:
      ids.level = define_icon_index_axis(f, "height", dim_level, "generalized_height");
      ids.height_2 = define_icon_index_axis(f, "height_2", dim_half, "generalized_height");
      ids.z_ifc = define_height_field(f, "z_ifc", dim_half, dim_lat, dim_lon,
                                      "geometric height at half level center", plane,
                                      spec.deflate);
      if (options.write_z_mc) {
        ids.z_mc = define_height_field(f, "z_mc", dim_level, dim_lat, dim_lon,
                                       "geometric height at full level center", plane,
                                       spec.deflate);
      }
      ids.surface = define_surface(f, "topography_c", dim_lat, dim_lon,
                                   "geometric height of the earth's surface above sea level");
      break;
    case SampleModel::kIconCf:
      ids.level = f.variable("lev", Type::kDouble, {dim_level});
      put_axis_attributes(f, ids.level, "atmosphere_hybrid_height_coordinate",
                          "atmosphere hybrid height coordinate", "m", "Z");
      f.text(ids.level, "positive", "up");
      f.text(ids.level, "formula_terms", "a: lev b: b orog: orog");
      ids.b = f.variable("b", Type::kDouble, {dim_level});
      f.text(ids.b, "long_name", "vertical coordinate formula term: b(k)");
      f.text(ids.b, "units", "1");
      ids.surface = define_surface(f, "orog", dim_lat, dim_lon, "surface altitude");
      break;
    case SampleModel::kSigmaPressure: {
      ids.level = f.variable("lev", Type::kDouble, {dim_level});
      put_axis_attributes(f, ids.level, "atmosphere_hybrid_sigma_pressure_coordinate",
                          "hybrid sigma-pressure level at layer midpoints", "1", "Z");
      f.text(ids.level, "positive", "down");
      f.text(ids.level, "formula_terms", "ap: hyam b: hybm ps: ps");
      ids.hyam = f.variable("hyam", Type::kDouble, {dim_level});
      f.text(ids.hyam, "long_name", "hybrid A coefficient at layer midpoints");
      f.text(ids.hyam, "units", "Pa");
      ids.hybm = f.variable("hybm", Type::kDouble, {dim_level});
      f.text(ids.hybm, "long_name", "hybrid B coefficient at layer midpoints");
      f.text(ids.hybm, "units", "1");
      ids.ps = f.variable("ps", Type::kFloat, {dim_time, dim_lat, dim_lon});
      f.chunk_by_plane(ids.ps, plane, spec.deflate);
      f.text(ids.ps, "standard_name", "surface_air_pressure");
      f.text(ids.ps, "long_name", "surface pressure");
      f.text(ids.ps, "units", "Pa");
      ids.surface = define_surface(f, "orog", dim_lat, dim_lon, "surface altitude");
      break;
    }
    case SampleModel::kSample:
    case SampleModel::kWrf:
    case SampleModel::kCurvilinear:
      break;
  }

  const std::array<std::size_t, 4> chunk{1, 1, d.y, d.x};
  for (const ModelVariable& v : model_variables(model)) {
    const int var = f.variable(v.name, Type::kFloat, {dim_time, dim_level, dim_lat, dim_lon});
    f.chunk_by_plane(var, chunk, spec.deflate);
    f.text(var, "standard_name", v.standard_name);
    f.text(var, "long_name", v.long_name);
    f.text(var, "units", v.units);
    ids.variables.push_back(var);
  }

  f.text(ModelNetcdfFile::kGlobal, "Conventions", "CF-1.8");
  f.text(ModelNetcdfFile::kGlobal, "title",
         fmt::format("STRIELAD synthetic {}-like sample on terrain-following levels",
                     sample_model_name(model)));
  f.text(ModelNetcdfFile::kGlobal, "source",
         fmt::format("strielad-sample --model {}", sample_model_name(model)));
  f.text(ModelNetcdfFile::kGlobal, "comment",
         "Deterministic synthetic fields over the synthetic sample terrain; not model output.");
  f.unsigned_number(ModelNetcdfFile::kGlobal, "seed", spec.seed);
  return ids;
}

// Index values 1 .. n.
std::vector<double> level_numbers(std::size_t n) {
  std::vector<double> v(n);
  for (std::size_t k = 0; k < n; ++k) v[k] = static_cast<double>(k + 1);
  return v;
}

// What every file of one dataset shares.
struct DatasetContext {
  const SampleSpec& spec;
  SampleModel model;
  const SampleGrid& grid;
  const std::vector<float>& surface;
  const HybridHeightLevels& height_levels;
  const HybridPressureLevels& pressure_levels;
};

void write_time_invariant(ModelNetcdfFile& f, const FileIds& ids, const DatasetContext& ctx) {
  const std::size_t nz = ctx.spec.dims.z, n = ctx.grid.level_size();
  const HybridHeightLevels& hl = ctx.height_levels;
  f.put(ids.lat, std::span<const double>(ctx.grid.lat));
  f.put(ids.lon, std::span<const double>(ctx.grid.lon));
  f.put(ids.surface, std::span<const float>(ctx.surface));
  const auto write_heights = [&](int var, const std::vector<double>& a,
                                 const std::vector<double>& b) {
    std::vector<float> plane(n);
    for (std::size_t k = 0; k < a.size(); ++k) {
      for (std::size_t c = 0; c < n; ++c) {
        plane[c] = static_cast<float>(a[k] + b[k] * static_cast<double>(ctx.surface[c]));
      }
      const std::array<std::size_t, 3> start{k, 0, 0}, count{1, ctx.spec.dims.y, ctx.spec.dims.x};
      f.put(var, start, count, plane);
    }
  };
  switch (ctx.model) {
    case SampleModel::kIcon:
      f.put(ids.level, std::span<const double>(level_numbers(nz)));
      f.put(ids.height_2, std::span<const double>(level_numbers(nz + 1)));
      write_heights(ids.z_ifc, hl.half_a, hl.half_b);
      if (ids.z_mc >= 0) write_heights(ids.z_mc, hl.full_a, hl.full_b);
      break;
    case SampleModel::kIconCf:
      f.put(ids.level, std::span<const double>(hl.full_a));
      f.put(ids.b, std::span<const double>(hl.full_b));
      break;
    case SampleModel::kSigmaPressure: {
      const HybridPressureLevels& pl = ctx.pressure_levels;
      std::vector<double> lev(nz);
      for (std::size_t k = 0; k < nz; ++k) {
        lev[k] = pl.full_ap[k] / kHybridReferencePressure + pl.full_b[k];
      }
      f.put(ids.level, std::span<const double>(lev));
      f.put(ids.hyam, std::span<const double>(pl.full_ap));
      f.put(ids.hybm, std::span<const double>(pl.full_b));
      break;
    }
    case SampleModel::kSample:
    case SampleModel::kWrf:
    case SampleModel::kCurvilinear:
      break;
  }
}

// The height above sea level of full level k in every column.
void level_heights(const DatasetContext& ctx, const ModelAtmosphere& atmosphere, std::size_t k,
                   std::vector<double>& z) {
  const std::size_t n = ctx.grid.level_size();
  if (ctx.model == SampleModel::kSigmaPressure) {
    const HybridPressureLevels& pl = ctx.pressure_levels;
    const std::span<const double> ps = atmosphere.surface_pressure();
    for (std::size_t c = 0; c < n; ++c) {
      z[c] = atmosphere.height_at_pressure(c, pl.full_ap[k] + pl.full_b[k] * ps[c]);
    }
    return;
  }
  const HybridHeightLevels& hl = ctx.height_levels;
  for (std::size_t c = 0; c < n; ++c) {
    z[c] = hl.full_a[k] + hl.full_b[k] * static_cast<double>(ctx.surface[c]);
  }
}

SampleFile write_model_file(const std::filesystem::path& path, const DatasetContext& ctx,
                            const ModelSampleOptions& options, std::span<const double> times,
                            const std::function<void()>& level_done) {
  const SampleSpec& spec = ctx.spec;
  const std::size_t nx = spec.dims.x, ny = spec.dims.y, n = ctx.grid.level_size();
  ModelNetcdfFile f(path);
  const FileIds ids = define_file(f, ctx.model, spec, options);
  f.end_define();
  write_time_invariant(f, ids, ctx);
  std::vector<double> time_values(times.begin(), times.end());
  if (ctx.model == SampleModel::kIcon) {
    for (double& t : time_values) t = icon_day_value(t);
  }
  const std::array<std::size_t, 1> time_start{0}, time_count{time_values.size()};
  f.put(ids.time, time_start, time_count, std::span<const double>(time_values));

  const std::span<const ModelVariable> variables = model_variables(ctx.model);
  std::vector<double> z(n);
  std::vector<float> values(n);
  for (std::size_t s = 0; s < times.size(); ++s) {
    const ModelAtmosphere atmosphere(ctx.grid, ctx.surface, spec.seed, times[s]);
    if (ids.ps >= 0) {
      const std::span<const double> ps = atmosphere.surface_pressure();
      for (std::size_t c = 0; c < n; ++c) values[c] = static_cast<float>(ps[c]);
      const std::array<std::size_t, 3> start{s, 0, 0}, count{1, ny, nx};
      f.put(ids.ps, start, count, values);
    }
    for (std::size_t v = 0; v < variables.size(); ++v) {
      for (std::size_t k = 0; k < spec.dims.z; ++k) {
        level_heights(ctx, atmosphere, k, z);
        atmosphere.fill(variables[v].field, z, values);
        const std::array<std::size_t, 4> start{s, k, 0, 0}, count{1, 1, ny, nx};
        f.put(ids.variables[v], start, count, values);
        level_done();
      }
    }
  }
  const std::uint64_t bytes = f.commit();
  return SampleFile{path, bytes};
}

}  // namespace

std::string_view sample_model_name(SampleModel model) noexcept {
  switch (model) {
    case SampleModel::kSample:
      return "sample";
    case SampleModel::kIcon:
      return "icon";
    case SampleModel::kIconCf:
      return "icon-cf";
    case SampleModel::kSigmaPressure:
      return "sigma-pressure";
    case SampleModel::kWrf:
      return "wrf";
    case SampleModel::kCurvilinear:
      return "curvilinear";
  }
  return "?";
}

std::vector<std::string> model_sample_variable_names(SampleModel model) {
  file_prefix(model);  // throws for kSample
  if (model == SampleModel::kWrf) return wrf_sample_variable_names();
  std::vector<std::string> names;
  for (const ModelVariable& v : model_variables(model)) names.emplace_back(v.name);
  return names;
}

std::vector<std::string> model_sample_file_names(const SampleSpec& spec, SampleModel model) {
  const char* prefix = file_prefix(model);
  if (model == SampleModel::kWrf) return wrf_sample_file_names(spec);
  std::vector<std::string> names;
  if (!spec.file_per_step) {
    names.push_back(fmt::format("{}.nc", prefix));
    return names;
  }
  for (std::size_t s = 0; s < spec.steps; ++s) names.push_back(fmt::format("{}_t{:03d}.nc", prefix, s));
  return names;
}

SampleResult write_model_like_dataset(const SampleSpec& spec, SampleModel model,
                                      const std::filesystem::path& out_dir,
                                      const ModelSampleOptions& options,
                                      SampleProgress progress) {
  if (model == SampleModel::kWrf) return write_wrf_like_dataset(spec, out_dir, std::move(progress));
  if (model == SampleModel::kCurvilinear) {
    return write_curvilinear_like_dataset(spec, out_dir, std::move(progress));
  }
  validate_sample_spec(spec);
  const std::vector<std::string> names = model_sample_file_names(spec, model);
  prepare_sample_directory(out_dir);

  const SampleGrid grid(spec.dims);
  const std::vector<float> surface = sample_terrain_heights(grid.lon, grid.lat, spec.seed);
  const HybridHeightLevels height_levels = hybrid_height_levels(spec.dims.z);
  const HybridPressureLevels pressure_levels = hybrid_pressure_levels(spec.dims.z);
  const DatasetContext ctx{spec, model, grid, surface, height_levels, pressure_levels};

  return write_step_files(
      spec, out_dir, names, static_cast<std::uint64_t>(model_variables(model).size()) * spec.dims.z,
      [&](const std::filesystem::path& path, std::span<const double> times,
          const std::function<void()>& level_done) {
        return write_model_file(path, ctx, options, times, level_done);
      },
      progress);
}

}  // namespace strielad::synthetic
