// SPDX-License-Identifier: Apache-2.0
#include "synthetic/model_atmosphere.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "synthetic/atmosphere_profiles.h"
#include "synthetic/hash_noise.h"

namespace strielad::synthetic {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kKmPerDegree = 111.32;
constexpr std::uint64_t kSaltModelGeometry = 41;  // phases and positions of this atmosphere

// The cloud blob: horizontal radius, height of its centre above the ground and vertical
// half-thickness (m), the part of the Gaussian that is cloud, the peak cloud water.
constexpr double kBlobRadiusKm = 120.0, kBlobHeight = 2000.0, kBlobThickness = 1200.0;
constexpr double kBlobThreshold = 0.4, kBlobCloudWater = 1.4e-3;

double slope(std::span<const float> surface, std::size_t c, std::size_t stride, std::size_t i,
             std::size_t n, double spacing_m) {
  if (n < 2 || spacing_m <= 0) return 0.0;
  const std::size_t lo = i == 0 ? c : c - stride, hi = i + 1 == n ? c : c + stride;
  const double steps = static_cast<double>((i + 1 == n ? i : i + 1) - (i == 0 ? 0 : i - 1));
  return (surface[hi] - surface[lo]) / (steps * spacing_m);
}

}  // namespace

ModelAtmosphere::ModelAtmosphere(const SampleGrid& grid, std::span<const float> surface,
                                 std::uint64_t seed, double time_seconds)
    : grid_(grid), surface_(surface) {
  const std::size_t nx = grid.dims.x, ny = grid.dims.y, n = grid.level_size();
  if (surface.size() != n) {
    throw make_error(ErrorCode::kInternal, "model sample: {} surface heights for {} columns",
                     surface.size(), n);
  }
  for (auto* v : {&dt_, &p_sea_, &ps_, &vortex_u_, &vortex_v_, &jet_, &slope_x_, &slope_y_}) {
    v->resize(n);
  }
  const std::uint64_t key = noise_key(seed, kSaltModelGeometry);
  const auto u = [key](std::uint64_t i) { return unit_hash(key, i); };
  const double t_km = time_seconds / 1000.0;  // km travelled per m/s
  // A warm wave travelling east at 10 m/s; the cyclone drifting east-north-east; the
  // cloud blob drifting with the low-level westerly.
  const double wave_phase = 2 * kPi * u(0);
  const double cx = -220.0 + 80.0 * u(1) + 11.0 * t_km, cy = 110.0 + 60.0 * u(2) + 3.0 * t_km;
  blob_x_km_ = -120.0 + 120.0 * u(3) + 8.0 * t_km;
  blob_y_km_ = -60.0 + 120.0 * u(4) + kMeanSoutherly * t_km;
  const double jet_y = -40.0 + 80.0 * u(5);
  constexpr double kVortexRadius = 150.0, kVortexMax = 15.0, kAlpha = 1.25643;
  const double dx_m = nx > 1 ? (grid.x_km[1] - grid.x_km[0]) * 1000.0 : 0.0;
  const double dy_m = ny > 1 ? (grid.y_km[1] - grid.y_km[0]) * 1000.0 : 0.0;

  tbb::parallel_for(std::size_t{0}, ny, [&](std::size_t j) {
    const double y = grid.y_km[j];
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t c = j * nx + i;
      const double x = grid.x_km[i];
      dt_[c] = -0.55 * y / kKmPerDegree + 1.5 * std::sin(2 * kPi * (x - 10.0 * t_km) / 700.0 +
                                                         wave_phase);
      const double dx = x - cx, dy = y - cy, r2 = dx * dx + dy * dy;
      p_sea_[c] = kSurfacePressure - 0.9 * y - 1500.0 * std::exp(-r2 / (250.0 * 250.0));
      ps_[c] = column_pressure(surface[c], p_sea_[c], dt_[c]);
      const double vt_over_r =
          r2 > 1e-18 ? kVortexMax * (1 + 0.5 / kAlpha) * kVortexRadius *
                           -std::expm1(-kAlpha * r2 / (kVortexRadius * kVortexRadius)) / r2
                     : 0.0;
      vortex_u_[c] = -vt_over_r * dy;  // counter-clockwise
      vortex_v_[c] = vt_over_r * dx;
      const double dj = (y - jet_y) / 300.0;
      jet_[c] = std::exp(-dj * dj);
      slope_x_[c] = slope(surface, c, 1, i, nx, dx_m);
      slope_y_[c] = slope(surface, c, nx, j, ny, dy_m);
    }
  });
}

double ModelAtmosphere::height_at_pressure(std::size_t c, double p) const {
  return column_height(p, p_sea_[c], dt_[c]);
}

double ModelAtmosphere::cloud_shape(std::size_t c, double height_above_ground) const {
  const std::size_t nx = grid_.dims.x;
  const double dx = (grid_.x_km[c % nx] - blob_x_km_) / kBlobRadiusKm;
  const double dy = (grid_.y_km[c / nx] - blob_y_km_) / kBlobRadiusKm;
  const double dz = (height_above_ground - kBlobHeight) / kBlobThickness;
  return std::exp(-(dx * dx + dy * dy + dz * dz));
}

float ModelAtmosphere::value(ModelField field, std::size_t c, double z) const {
  const double agl = std::max(z - static_cast<double>(surface_[c]), 0.0);
  const double bl = boundary_layer_factor(agl);
  const double vortex = vortex_height_factor(agl) * bl;
  switch (field) {
    case ModelField::kTemperature:
      return static_cast<float>(standard_temperature(z) + dt_[c] + 2.0 * std::exp(-agl / 400.0));
    case ModelField::kCloudWater: {
      const double g = cloud_shape(c, agl);
      return static_cast<float>(
          g > kBlobThreshold ? kBlobCloudWater * (g - kBlobThreshold) / (1 - kBlobThreshold) : 0.0);
    }
    case ModelField::kSpecificHumidity:
      return static_cast<float>(
          std::max(3e-6, 0.009 * std::exp(-agl / 2200.0) * (1.0 + 0.04 * dt_[c])));
    case ModelField::kEastward:
      return static_cast<float>(bl * (background_westerly(z) + jet_core_speed(z) * jet_[c]) +
                                vortex * vortex_u_[c]);
    case ModelField::kNorthward:
      return static_cast<float>(bl * kMeanSoutherly + vortex * vortex_v_[c]);
    case ModelField::kUpward: {
      const double ua = value(ModelField::kEastward, c, z), va = value(ModelField::kNorthward, c, z);
      const double upslope = (ua * slope_x_[c] + va * slope_y_[c]) * std::exp(-agl / 1500.0);
      return static_cast<float>(upslope + 1.2 * cloud_shape(c, agl));
    }
    case ModelField::kPressure:
      return static_cast<float>(column_pressure(z, p_sea_[c], dt_[c]));
  }
  throw make_error(ErrorCode::kInternal, "model sample: unknown field {}", static_cast<int>(field));
}

void ModelAtmosphere::fill(ModelField field, std::span<const double> z_asl,
                           std::span<float> out) const {
  const std::size_t n = grid_.level_size();
  if (z_asl.size() != n || out.size() != n) {
    throw make_error(ErrorCode::kInternal, "model sample: level of {} heights, {} values for {} columns",
                     z_asl.size(), out.size(), n);
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t c = r.begin(); c != r.end(); ++c) {
                        out[c] = value(field, c, z_asl[c]);
                      }
                    });
}

}  // namespace strielad::synthetic
