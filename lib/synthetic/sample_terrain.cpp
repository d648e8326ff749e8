// SPDX-License-Identifier: Apache-2.0
#include "synthetic/sample_terrain.h"

#include <netcdf.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <vector>

#include "core/error.h"
#include "geo/cf_grid_mapping.h"
#include "geo/grid_projection.h"
#include "geo/lon_lat.h"
#include "ingest/netcdf_call.h"
#include "synthetic/hash_noise.h"
#include "synthetic/sample_grid.h"

namespace strielad::synthetic {
namespace {

// The rotated pole of the regional models (COSMO-DE, EURO-CORDEX), as the file's CF
// grid mapping writes it.
constexpr double kPoleLat = 39.25, kPoleLon = -162.0;
constexpr float kFill = -9999.0f;

// The file's grid mapping placed as stores and DEMs are placed: its CF attributes
// through geo::cf_grid_mapping_proj, run by PROJ.
geo::GridProjection pole_projection() {
  GridMapping mapping;
  mapping.variable = "rotated_pole";
  mapping.name = "rotated_latitude_longitude";
  mapping.attributes = {{"grid_mapping_name", mapping.name},
                        {"grid_north_pole_latitude", kPoleLat},
                        {"grid_north_pole_longitude", kPoleLon}};
  Axis rlon, rlat;
  rlon.name = "rlon";
  rlat.name = "rlat";
  rlon.units = rlat.units = "degrees";
  return geo::GridProjection(geo::cf_grid_mapping_proj(mapping, rlon, rlat, "sample terrain"));
}

double smoothstep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

struct Range {
  double lon, lat, height_m, radius_km, stretch;  // stretch > 1: long along lon
};
// Low mountain ranges at roughly their real places.
constexpr std::array<Range, 8> kRanges{{{8.2, 48.2, 1100, 45, 0.6},   // Black Forest
                                        {10.6, 51.75, 900, 30, 1.8},  // Harz
                                        {13.0, 50.5, 850, 35, 3.0},   // Erzgebirge
                                        {13.3, 49.0, 1050, 40, 2.0},  // Bavarian Forest
                                        {7.4, 50.2, 650, 70, 1.5},    // Rhenish Massif
                                        {10.8, 50.6, 750, 30, 2.5},   // Thuringian Forest
                                        {9.5, 48.4, 800, 40, 2.5},    // Swabian Jura
                                        {6.5, 48.3, 900, 35, 0.6}}};  // Vosges

bool is_sea(double lon, double lat) {
  const bool north_sea = lat > 53.45 + 0.25 * std::sin(lon * 3.1) && lon < 8.9 &&
                         !(lon > 8.3 && lat < 53.6);
  const bool baltic = lat > 54.15 + 0.15 * std::cos(lon * 2.3) && lon > 10.1;
  return north_sea || baltic;
}

void check(int status, const std::filesystem::path& path) {
  ingest::nc_check(status, path.string());
}

}  // namespace

namespace {

// The rotated axes of an n x n grid over the domain's rotated box, 3% wider on each side.
struct RotatedAxes {
  std::vector<double> rlon, rlat;
};

RotatedAxes rotated_axes(const geo::GridProjection& pole, std::size_t n) {
  double rlon0 = INFINITY, rlon1 = -INFINITY, rlat0 = INFINITY, rlat1 = -INFINITY;
  for (int i = 0; i <= 100; ++i) {
    const double t = i / 100.0;
    const double lon = kLonMin + t * (kLonMax - kLonMin), lat = kLatMin + t * (kLatMax - kLatMin);
    for (const auto& [x, y] : {std::pair{lon, kLatMin}, std::pair{lon, kLatMax},
                               std::pair{kLonMin, lat}, std::pair{kLonMax, lat}}) {
      const auto r = pole.to_axis(x, y);
      rlon0 = std::min(rlon0, r[0]);
      rlon1 = std::max(rlon1, r[0]);
      rlat0 = std::min(rlat0, r[1]);
      rlat1 = std::max(rlat1, r[1]);
    }
  }
  const double mx = 0.03 * (rlon1 - rlon0), my = 0.03 * (rlat1 - rlat0);
  rlon0 -= mx, rlon1 += mx, rlat0 -= my, rlat1 += my;
  RotatedAxes axes{std::vector<double>(n), std::vector<double>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    axes.rlon[i] = rlon0 + (rlon1 - rlon0) * double(i) / double(n - 1);
    axes.rlat[i] = rlat0 + (rlat1 - rlat0) * double(i) / double(n - 1);
  }
  return axes;
}

// The two noise fields of the land: detail and ridges (on rotated km).
constexpr FbmParams kDetailNoise{.wavelength_km = 60, .wavelength_z_km = 1, .octaves = 6, .gain = 0.5};
constexpr FbmParams kRidgeNoise{.wavelength_km = 25, .wavelength_z_km = 1, .octaves = 5,
                                .gain = 0.55, .stretch_x = 2.5};
constexpr std::uint64_t kDetailSalt = 0x7e77a1, kRidgeSalt = 0x7e77a2;

// Height in m of the land at (lon, lat), from the detail noise `d` and the ridged noise `r`.
double land_height(const geo::LonLat& g, double d, double r) {
  // Lowlands rising to the south, the Alpine foreland, the Alps.
  double h = 30 + 420 * smoothstep(53.5, 49.0, g.lat) + 120 * d;
  h += 250 * smoothstep(49.0, 47.9, g.lat);
  const double alps = smoothstep(48.05, 47.45, g.lat + 0.08 * std::sin(g.lon * 1.7));
  h += alps * (1400 + 2200 * r * r + 500 * d);
  for (const auto& m : kRanges) {
    const double dx = (g.lon - m.lon) * 111.195 * std::cos(m.lat * 3.14159265 / 180.0) / m.stretch;
    const double dy = (g.lat - m.lat) * 111.195;
    const double q = (dx * dx + dy * dy) / (m.radius_km * m.radius_km);
    h += m.height_m * std::exp(-q) * (0.65 + 0.5 * r);
  }
  // Coasts slope down to the sea.
  return std::max(h * (0.4 + 0.6 * smoothstep(54.4, 53.0, g.lat)) + 60 * d, 1.0);
}

// HSURF (sea: _FillValue) and the geographic position of every sample, rows by rlat.
struct TerrainFields {
  std::vector<float> hsurf, lat, lon;
  float max_height_m = 0;
};

TerrainFields terrain_fields(const SampleTerrainSpec& spec, const geo::GridProjection& pole,
                             const RotatedAxes& axes) {
  const std::size_t n = axes.rlon.size();
  std::vector<double> x_km(n), y_km(n);
  for (std::size_t i = 0; i < n; ++i) {
    x_km[i] = axes.rlon[i] * 111.195;
    y_km[i] = axes.rlat[i] * 111.195;
  }
  const FbmPlane detail(kDetailNoise, noise_key(spec.seed, kDetailSalt), x_km, y_km, 0.0);
  const FbmPlane ridges(kRidgeNoise, noise_key(spec.seed, kRidgeSalt), x_km, y_km, 0.0);
  TerrainFields out{std::vector<float>(n * n), std::vector<float>(n * n),
                    std::vector<float>(n * n)};
  std::vector<float> row_detail(n), row_ridges(n);
  for (std::size_t j = 0; j < n; ++j) {
    detail.row(j, row_detail);
    ridges.row(j, row_ridges);
    for (std::size_t i = 0; i < n; ++i) {
      const auto [lon, lat] = pole.to_geographic(axes.rlon[i], axes.rlat[j]);
      const geo::LonLat g{lon, lat};
      out.lon[j * n + i] = static_cast<float>(g.lon);
      out.lat[j * n + i] = static_cast<float>(g.lat);
      if (is_sea(g.lon, g.lat)) {
        out.hsurf[j * n + i] = kFill;
        continue;
      }
      const double r = 1.0 - std::fabs(row_ridges[i]);  // ridged noise
      out.hsurf[j * n + i] = static_cast<float>(land_height(g, row_detail[i], r));
      out.max_height_m = std::max(out.max_height_m, out.hsurf[j * n + i]);
    }
  }
  return out;
}

// The CF-NetCDF terrain file `tmp`: rotated axes, the pole, 2-D lat/lon and HSURF.
void write_terrain_netcdf(const std::filesystem::path& tmp, const RotatedAxes& axes,
                          const TerrainFields& fields) {
  const std::size_t n = axes.rlon.size();
  int nc = -1;
  check(nc_create(tmp.c_str(), NC_CLOBBER | NC_NETCDF4, &nc), tmp);
  try {
    int drlat = 0, drlon = 0, vrlat = 0, vrlon = 0, vh = 0, vlat = 0, vlon = 0, vpole = 0;
    check(nc_def_dim(nc, "rlat", n, &drlat), tmp);
    check(nc_def_dim(nc, "rlon", n, &drlon), tmp);
    const auto text = [&](int var, const char* name, const std::string& value) {
      check(nc_put_att_text(nc, var, name, value.size(), value.c_str()), tmp);
    };
    check(nc_def_var(nc, "rlat", NC_DOUBLE, 1, &drlat, &vrlat), tmp);
    text(vrlat, "standard_name", "grid_latitude");
    text(vrlat, "units", "degrees");
    check(nc_def_var(nc, "rlon", NC_DOUBLE, 1, &drlon, &vrlon), tmp);
    text(vrlon, "standard_name", "grid_longitude");
    text(vrlon, "units", "degrees");
    check(nc_def_var(nc, "rotated_pole", NC_CHAR, 0, nullptr, &vpole), tmp);
    text(vpole, "grid_mapping_name", "rotated_latitude_longitude");
    const double pole_lat = kPoleLat, pole_lon = kPoleLon;
    check(nc_put_att_double(nc, vpole, "grid_north_pole_latitude", NC_DOUBLE, 1, &pole_lat), tmp);
    check(nc_put_att_double(nc, vpole, "grid_north_pole_longitude", NC_DOUBLE, 1, &pole_lon), tmp);
    const int dims2[2] = {drlat, drlon};
    check(nc_def_var(nc, "lat", NC_FLOAT, 2, dims2, &vlat), tmp);
    text(vlat, "standard_name", "latitude");
    text(vlat, "units", "degrees_north");
    check(nc_def_var(nc, "lon", NC_FLOAT, 2, dims2, &vlon), tmp);
    text(vlon, "standard_name", "longitude");
    text(vlon, "units", "degrees_east");
    check(nc_def_var(nc, "HSURF", NC_FLOAT, 2, dims2, &vh), tmp);
    text(vh, "standard_name", "surface_altitude");
    text(vh, "long_name", "surface height (synthetic)");
    text(vh, "units", "m");
    text(vh, "grid_mapping", "rotated_pole");
    text(vh, "coordinates", "lon lat");
    check(nc_put_att_float(nc, vh, "_FillValue", NC_FLOAT, 1, &kFill), tmp);
    for (const int v : {vlat, vlon, vh}) check(nc_def_var_deflate(nc, v, 1, 1, 1), tmp);
    text(NC_GLOBAL, "Conventions", "CF-1.8");
    text(NC_GLOBAL, "title", "STRIELAD sample terrain (synthetic, deterministic)");
    check(nc_enddef(nc), tmp);
    check(nc_put_var_double(nc, vrlat, axes.rlat.data()), tmp);
    check(nc_put_var_double(nc, vrlon, axes.rlon.data()), tmp);
    check(nc_put_var_float(nc, vlat, fields.lat.data()), tmp);
    check(nc_put_var_float(nc, vlon, fields.lon.data()), tmp);
    check(nc_put_var_float(nc, vh, fields.hsurf.data()), tmp);
    check(nc_close(nc), tmp);
  } catch (...) {
    nc_close(nc);
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    throw;
  }
}

}  // namespace

SampleTerrainResult write_sample_terrain(const SampleTerrainSpec& spec,
                                         const std::filesystem::path& path) {
  if (spec.samples < 2 || spec.samples > 16384) {
    throw make_error(ErrorCode::kInvalidArgument, "--terrain {}: must be 2 to 16384 samples",
                     spec.samples);
  }
  const geo::GridProjection pole = pole_projection();
  const RotatedAxes axes = rotated_axes(pole, spec.samples);
  const TerrainFields fields = terrain_fields(spec, pole, axes);
  SampleTerrainResult result;
  result.width = result.height = spec.samples;
  result.max_height_m = fields.max_height_m;

  std::error_code ec;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
  const auto tmp = std::filesystem::path(path.string() + ".tmp");
  {
    std::lock_guard lock(ingest::netcdf_mutex());
    write_terrain_netcdf(tmp, axes, fields);
    std::filesystem::rename(tmp, path, ec);
  }
  if (ec) {
    throw make_error(ErrorCode::kIo, "{}: cannot rename from {}: {}", path.string(), tmp.string(),
                     ec.message());
  }
  result.bytes = std::filesystem::file_size(path, ec);
  return result;
}

std::vector<float> sample_terrain_heights(std::span<const double> lon, std::span<const double> lat,
                                          std::uint64_t seed) {
  const std::size_t nx = lon.size(), ny = lat.size();
  std::vector<double> point_lon(nx * ny), point_lat(nx * ny);
  for (std::size_t j = 0; j < ny; ++j) {
    for (std::size_t i = 0; i < nx; ++i) {
      point_lon[j * nx + i] = lon[i];
      point_lat[j * nx + i] = lat[j];
    }
  }
  return sample_terrain_heights_at(point_lon, point_lat, seed);
}

std::vector<float> sample_terrain_heights_at(std::span<const double> lon,
                                             std::span<const double> lat, std::uint64_t seed) {
  if (lon.size() != lat.size()) {
    throw make_error(ErrorCode::kInternal, "sample terrain: {} longitudes for {} latitudes",
                     lon.size(), lat.size());
  }
  const std::size_t n = lon.size();
  const geo::GridProjection pole = pole_projection();
  // The rotated position of every point (serial: a PROJ object serves one thread), then
  // the noise of write_sample_terrain's planes at that position, one point at a time.
  std::vector<double> x_km(n), y_km(n);
  for (std::size_t p = 0; p < n; ++p) {
    const auto r = pole.to_axis(lon[p], lat[p]);
    x_km[p] = r[0] * 111.195;
    y_km[p] = r[1] * 111.195;
  }
  const std::uint64_t detail_key = noise_key(seed, kDetailSalt), ridges_key = noise_key(seed, kRidgeSalt);
  std::vector<float> out(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t p) {
    const geo::LonLat g{lon[p], lat[p]};
    if (is_sea(g.lon, g.lat)) return;  // out[p] stays 0
    const std::span<const double> x(&x_km[p], 1), y(&y_km[p], 1);
    const float d = FbmPlane(kDetailNoise, detail_key, x, y, 0.0).at(0, 0);
    const double r = 1.0 - std::fabs(FbmPlane(kRidgeNoise, ridges_key, x, y, 0.0).at(0, 0));
    out[p] = static_cast<float>(land_height(g, d, r));
  });
  return out;
}

}  // namespace strielad::synthetic
