// SPDX-License-Identifier: Apache-2.0
#include "synthetic/curvilinear_like_file.h"

#include <fmt/format.h>

#include <array>
#include <functional>
#include <span>

#include "core/error.h"
#include "geo/grid_projection.h"
#include "synthetic/model_atmosphere.h"
#include "synthetic/model_netcdf_file.h"
#include "synthetic/model_variables.h"
#include "synthetic/sample_grid.h"
#include "synthetic/sample_terrain.h"
#include "synthetic/sample_writer.h"

namespace strielad::synthetic {
namespace {

using Type = ModelNetcdfFile::Type;

// The ICON sample's variables, on the curvilinear grid.
constexpr const auto& kVariables = kIconVariables;

struct FileIds {
  int time = -1, height = -1, lat = -1, lon = -1;
  std::vector<int> variables;
};

FileIds define_file(ModelNetcdfFile& f, const SampleSpec& spec) {
  const Dims3& d = spec.dims;
  FileIds ids;
  const int dim_time = f.dimension("time", 0);
  const int dim_height = f.dimension("height", d.z);
  const int dim_y = f.dimension("y", d.y);
  const int dim_x = f.dimension("x", d.x);

  ids.time = f.variable("time", Type::kDouble, {dim_time});
  f.text(ids.time, "standard_name", "time");
  f.text(ids.time, "units", kSampleTimeUnits);
  f.text(ids.time, "calendar", "proleptic_gregorian");
  f.text(ids.time, "axis", "T");
  ids.height = f.variable("height", Type::kDouble, {dim_height});
  f.text(ids.height, "standard_name", "altitude");
  f.text(ids.height, "long_name", "height above mean sea level");
  f.text(ids.height, "units", "m");
  f.text(ids.height, "positive", "up");
  f.text(ids.height, "axis", "Z");
  ids.lat = f.variable("lat", Type::kDouble, {dim_y, dim_x});
  f.text(ids.lat, "standard_name", "latitude");
  f.text(ids.lat, "long_name", "latitude");
  f.text(ids.lat, "units", "degrees_north");
  ids.lon = f.variable("lon", Type::kDouble, {dim_y, dim_x});
  f.text(ids.lon, "standard_name", "longitude");
  f.text(ids.lon, "long_name", "longitude");
  f.text(ids.lon, "units", "degrees_east");

  const std::array<std::size_t, 4> chunk{1, 1, d.y, d.x};
  for (const ModelVariable& v : kVariables) {
    const int var = f.variable(v.name, Type::kFloat, {dim_time, dim_height, dim_y, dim_x});
    f.chunk_by_plane(var, chunk, spec.deflate);
    f.text(var, "standard_name", v.standard_name);
    f.text(var, "long_name", v.long_name);
    f.text(var, "units", v.units);
    f.text(var, "coordinates", "lon lat");
    ids.variables.push_back(var);
  }
  f.text(ModelNetcdfFile::kGlobal, "Conventions", "CF-1.8");
  f.text(ModelNetcdfFile::kGlobal, "title",
         "STRIELAD synthetic sample on a rotated-pole grid placed by 2-D latitude/longitude");
  f.text(ModelNetcdfFile::kGlobal, "source", "strielad-sample --model curvilinear");
  f.text(ModelNetcdfFile::kGlobal, "comment",
         fmt::format("Deterministic synthetic fields; not model output. lat/lon: {}",
                     curvilinear_sample_proj_string()));
  f.unsigned_number(ModelNetcdfFile::kGlobal, "seed", spec.seed);
  return ids;
}

struct DatasetContext {
  const SampleSpec& spec;
  const CurvilinearSampleGrid& grid;
  const SampleGrid& atmosphere_grid;  // the sample's grid of the same size: the fields
  const std::vector<float>& surface;
};

SampleFile write_file(const std::filesystem::path& path, const DatasetContext& ctx,
                      std::span<const double> times, const std::function<void()>& level_done) {
  const SampleSpec& spec = ctx.spec;
  const std::size_t nx = spec.dims.x, ny = spec.dims.y, n = nx * ny;
  ModelNetcdfFile f(path);
  const FileIds ids = define_file(f, spec);
  f.end_define();
  f.put(ids.height, std::span<const double>(ctx.atmosphere_grid.height));
  f.put(ids.lat, std::span<const double>(ctx.grid.lat));
  f.put(ids.lon, std::span<const double>(ctx.grid.lon));
  const std::array<std::size_t, 1> time_start{0}, time_count{times.size()};
  f.put(ids.time, time_start, time_count, times);

  std::vector<double> z(n);
  std::vector<float> values(n);
  for (std::size_t s = 0; s < times.size(); ++s) {
    const ModelAtmosphere atmosphere(ctx.atmosphere_grid, ctx.surface, spec.seed, times[s]);
    for (std::size_t v = 0; v < kVariables.size(); ++v) {
      for (std::size_t k = 0; k < spec.dims.z; ++k) {
        std::fill(z.begin(), z.end(), ctx.atmosphere_grid.height[k]);
        atmosphere.fill(kVariables[v].field, z, values);
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

std::string curvilinear_sample_proj_string() {
  return fmt::format("+proj=ob_tran +o_proj=longlat +o_lat_p={} +o_lon_p=0 +lon_0={}",
                     kCurvilinearPoleLat, 180.0 + kCurvilinearPoleLon);
}

CurvilinearSampleGrid curvilinear_sample_grid(std::size_t nx, std::size_t ny) {
  CurvilinearSampleGrid g;
  g.nx = nx;
  g.ny = ny;
  g.rlon = uniform_axis(nx, kCurvilinearRlonMin, kCurvilinearRlonMax);
  g.rlat = uniform_axis(ny, kCurvilinearRlatMin, kCurvilinearRlatMax);
  const geo::GridProjection projection(fmt::format(
      "+proj=pipeline +step +proj=unitconvert +xy_in=deg +xy_out=rad +step +inv {} +step "
      "+proj=unitconvert +xy_in=rad +xy_out=deg",
      curvilinear_sample_proj_string()));
  g.lon.resize(nx * ny);
  g.lat.resize(nx * ny);
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      const auto p = projection.to_geographic(g.rlon[i], g.rlat[j]);
      g.lon[j * nx + i] = p[0];
      g.lat[j * nx + i] = p[1];
    }
  }
  return g;
}

std::vector<std::string> curvilinear_sample_file_names(const SampleSpec& spec) {
  std::vector<std::string> names;
  if (!spec.file_per_step) {
    names.emplace_back("curvilinear.nc");
    return names;
  }
  for (std::size_t s = 0; s < spec.steps; ++s) {
    names.push_back(fmt::format("curvilinear_t{:03d}.nc", s));
  }
  return names;
}

SampleResult write_curvilinear_like_dataset(const SampleSpec& spec,
                                            const std::filesystem::path& out_dir,
                                            SampleProgress progress) {
  validate_sample_spec(spec);
  const std::vector<std::string> names = curvilinear_sample_file_names(spec);
  prepare_sample_directory(out_dir);
  const CurvilinearSampleGrid grid = curvilinear_sample_grid(spec.dims.x, spec.dims.y);
  const SampleGrid atmosphere_grid(spec.dims);
  const std::vector<float> surface =
      sample_terrain_heights(atmosphere_grid.lon, atmosphere_grid.lat, spec.seed);
  const DatasetContext ctx{spec, grid, atmosphere_grid, surface};
  return write_step_files(
      spec, out_dir, names, static_cast<std::uint64_t>(kVariables.size()) * spec.dims.z,
      [&](const std::filesystem::path& path, std::span<const double> times,
          const std::function<void()>& level_done) {
        return write_file(path, ctx, times, level_done);
      },
      progress);
}

}  // namespace strielad::synthetic
