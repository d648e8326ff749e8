// SPDX-License-Identifier: Apache-2.0
#include "synthetic/sample_atmosphere.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "synthetic/atmosphere_profiles.h"

namespace strielad::synthetic {
namespace {

// Independent noise streams of one seed.
enum Salt : std::uint64_t {
  kSaltGeometry = 1,   // positions and phases of fronts, cyclone and jet
  kSaltLiquid = 11,    // liquid clouds (and the rain falling out of them)
  kSaltIce = 12,
  kSaltTemperature = 21,
  kSaltEastward = 22,
  kSaltNorthward = 23,
  kSaltVertical = 24,
  kSaltColumnTemperature = 31,
  kSaltSurfacePressure = 32,
};

constexpr double kPi = std::numbers::pi;
constexpr double kKmPerDegree = 111.32;
constexpr double kRainSourceHeight = 2200.0;   // m: rain falls out of clouds at this level
constexpr FbmParams kSmoothNoise{220.0, 5.0, 2, 0.5, 1.0};
constexpr FbmParams kSynopticNoise{400.0, 1.0, 2, 0.5, 1.0};

template <typename F>
void for_row_ranges(std::size_t rows, F&& body) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows),
                    [&](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); });
}

template <typename F>
void for_rows(std::size_t rows, F&& body) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t j = r.begin(); j != r.end(); ++j) body(j);
                    });
}

}  // namespace

const SampleAtmosphere::CloudSpecies SampleAtmosphere::kLiquid{
    kSaltLiquid, FbmParams{48.0, 2.5, 4, 0.5, 1.0}, 0.47f, 0.65f, 0.2f, 0.25f};
const SampleAtmosphere::CloudSpecies SampleAtmosphere::kIce{
    kSaltIce, FbmParams{60.0, 1.5, 4, 0.5, 2.5}, 0.28f, 0.45f, 0.3f, 0.30f};
const SampleAtmosphere::CloudSpecies SampleAtmosphere::kRainSource{
    kSaltLiquid, FbmParams{48.0, 2.5, 4, 0.5, 1.0}, 0.60f, 0.65f, 0.3f, 0.25f};

SampleAtmosphere::SampleAtmosphere(const SampleGrid& grid, std::uint64_t seed, double time_seconds)
    : grid_(grid), seed_(seed), time_(time_seconds) {
  const std::size_t nx = grid.dims.x, ny = grid.dims.y, n = grid.level_size();
  band_.resize(n);
  dt_.resize(n);
  ps_.resize(n);
  vortex_u_.resize(n);
  vortex_v_.resize(n);
  jet_.resize(n);
  meander_.resize(n);

  const std::uint64_t gkey = noise_key(seed, kSaltGeometry);
  const auto u = [gkey](std::uint64_t i) { return unit_hash(gkey, i); };
  const double t_km = time_seconds / 1000.0;  // km travelled per m/s

  // Cold front (and a weaker pre-frontal band) running SW-NE, moving south-east at
  // 7 m/s; (s, n) are along-front and across-front (towards north-west) coordinates.
  const double theta = (30.0 + 15.0 * u(0)) * kPi / 180.0;
  const double cos_t = std::cos(theta), sin_t = std::sin(theta);
  const double front_n0 = 100.0 + 80.0 * u(1) - 7.0 * t_km;
  const double front_amp = 70.0, front_k = 2 * kPi / 550.0, front_phase = 2 * kPi * u(2);
  // Cyclone: Lamb-Oseen vortex, radius of maximum wind 150 km, 15 m/s, drifting ENE.
  const double cx = -220.0 + 80.0 * u(3) + 11.0 * t_km;
  const double cy = 110.0 + 60.0 * u(4) + 3.0 * t_km;
  constexpr double kVortexRadius = 150.0, kVortexMax = 15.0, kAlpha = 1.25643;
  // Jet axis meandering around the domain centre, drifting east with the flow.
  const double jet_y0 = -40.0 + 80.0 * u(5), jet_amp = 60.0, jet_k = 2 * kPi / 900.0;
  const double jet_phase = 2 * kPi * u(6);
  constexpr double kJetHalfWidth = 300.0;

  const FbmPlane column_t(kSynopticNoise, noise_key(seed, kSaltColumnTemperature), grid.x_km,
                          grid.y_km, 0.0, 10.0 * t_km, kMeanSoutherly * t_km);
  const FbmPlane surface_p(kSynopticNoise, noise_key(seed, kSaltSurfacePressure), grid.x_km,
                           grid.y_km, 0.0, 10.0 * t_km, kMeanSoutherly * t_km);

  for_rows(ny, [&](std::size_t j) {
    const double y = grid.y_km[j];
    // Synoptic noise first, the rest of the row is computed around it.
    column_t.row(j, std::span<float>(dt_).subspan(j * nx, nx));
    surface_p.row(j, std::span<float>(ps_).subspan(j * nx, nx));
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t idx = j * nx + i;
      const double x = grid.x_km[i];
      // Fronts.
      const double s = x * cos_t + y * sin_t;
      const double nn = -x * sin_t + y * cos_t;
      const double d1 = (nn - (front_n0 + front_amp * std::sin(front_k * s + front_phase))) / 70.0;
      const double d2 =
          (nn - (front_n0 - 320.0 + 0.6 * front_amp * std::sin(front_k * s + front_phase + 1.3))) /
          40.0;
      // Cyclone.
      const double dx = x - cx, dy = y - cy;
      const double r2 = dx * dx + dy * dy;
      const double r = std::sqrt(r2);
      const double core = std::exp(-r2 / (250.0 * 250.0));
      double vt_over_r = 0;  // tangential speed / r
      if (r > 1e-9) {
        vt_over_r = kVortexMax * (1 + 0.5 / kAlpha) * kVortexRadius *
                    -std::expm1(-kAlpha * r2 / (kVortexRadius * kVortexRadius)) / r2;
      }
      band_[idx] = static_cast<float>(
          std::max({std::exp(-d1 * d1), 0.6 * std::exp(-d2 * d2), 0.6 * core}));
      vortex_u_[idx] = static_cast<float>(-vt_over_r * dy);  // counter-clockwise
      vortex_v_[idx] = static_cast<float>(vt_over_r * dx);
      // Column temperature: colder to the north, warm sector ahead of the cold front.
      const double lat_deg = y / kKmPerDegree;
      dt_[idx] = static_cast<float>(-0.55 * lat_deg + 1.5 * std::tanh(-d1 * 70.0 / 80.0) +
                                    1.2 * dt_[idx]);
      // Surface pressure: geostrophic westerly (lower to the north), cyclone low.
      ps_[idx] = static_cast<float>(kSurfacePressure - 0.9 * y - 1500.0 * core +
                                    250.0 * ps_[idx]);
      // Jet.
      const double yj = jet_y0 + jet_amp * std::sin(jet_k * (x - 12.0 * t_km) + jet_phase);
      const double dj = (y - yj) / kJetHalfWidth;
      const double w = std::exp(-dj * dj);
      jet_[idx] = static_cast<float>(w);
      meander_[idx] = static_cast<float>(
          w * jet_amp * jet_k * std::cos(jet_k * (x - 12.0 * t_km) + jet_phase));
    }
  });
  const auto [lo, hi] = std::minmax_element(dt_.begin(), dt_.end());
  dt_min_ = *lo;
  dt_max_ = *hi;
}

void SampleAtmosphere::fill_level(SampleVariable variable, std::size_t k,
                                  std::span<float> out) const {
  if (k >= grid_.dims.z || out.size() != grid_.level_size()) {
    throw make_error(ErrorCode::kInternal,
                     "sample: level {} of {} with a buffer of {} floats (need {})", k,
                     grid_.dims.z, out.size(), grid_.level_size());
  }
  const double z = grid_.height[k];
  const auto scale = [&](float factor) {
    for_rows(grid_.dims.y, [&](std::size_t j) {
      float* o = out.data() + j * grid_.dims.x;
      for (std::size_t i = 0; i < grid_.dims.x; ++i) o[i] *= factor;
    });
  };
  switch (variable) {
    case SampleVariable::kClw: {
      liquid_intensity(z, out);
      scale(1.1e-3f);
      return;
    }
    case SampleVariable::kCli:
      ice_intensity(z, out);
      scale(1.2e-4f);
      return;
    case SampleVariable::kQr:
      rain_intensity(z, out);
      scale(static_cast<float>(5e-4 * rain_evaporation(z)));
      return;
    case SampleVariable::kTa:
      fill_temperature(z, out);
      return;
    case SampleVariable::kPres:
      fill_pressure(z, out);
      return;
    case SampleVariable::kUa:
      fill_wind(true, z, out);
      return;
    case SampleVariable::kVa:
      fill_wind(false, z, out);
      return;
    case SampleVariable::kWa:
      fill_vertical_wind(z, out);
      return;
  }
  throw make_error(ErrorCode::kInternal, "sample: unknown variable {}",
                   static_cast<int>(variable));
}

void SampleAtmosphere::cloud_intensity(const CloudSpecies& species, double z_eval,
                                       double envelope, double shift_x_km, double shift_y_km,
                                       std::span<float> out) const {
  if (envelope <= 0) {
    std::fill(out.begin(), out.end(), 0.0f);
    return;
  }
  const FbmPlane fbm(species.noise, noise_key(seed_, species.salt), grid_.x_km, grid_.y_km,
                     z_eval / 1000.0, shift_x_km, shift_y_km);
  const float threshold =
      species.threshold + species.edge_penalty * static_cast<float>(1.0 - envelope);
  const float inv_width = 1.0f / species.width;
  const int octaves = fbm.octaves();
  const std::size_t nx = grid_.dims.x;
  for_row_ranges(grid_.dims.y, [&](std::size_t j0, std::size_t j1) {
    std::vector<float> need(nx), acc(nx);
    std::vector<std::uint32_t> active;
    active.reserve(nx);
    for (std::size_t j = j0; j < j1; ++j) {
      // Cloud where noise + band_gain * band exceeds the threshold. A column leaves the
      // active list as soon as the remaining octaves cannot lift it over the threshold.
      const float* band = band_.data() + j * nx;
      for (std::size_t i = 0; i < nx; ++i) need[i] = threshold - species.band_gain * band[i];
      std::fill(acc.begin(), acc.end(), 0.0f);
      fbm.octave(0).accumulate_row(j, fbm.amplitude(0), acc);
      active.clear();
      for (std::size_t i = 0; i < nx; ++i) {
        if (acc[i] + fbm.remaining(0) > need[i]) active.push_back(static_cast<std::uint32_t>(i));
      }
      for (int oc = 1; oc < octaves && !active.empty(); ++oc) {
        fbm.octave(oc).accumulate_columns(j, fbm.amplitude(oc), active, acc);
        const float rest = fbm.remaining(oc);
        std::size_t kept = 0;
        for (const std::uint32_t i : active) {
          if (acc[i] + rest > need[i]) active[kept++] = i;
        }
        active.resize(kept);
      }
      float* o = out.data() + j * nx;
      std::fill(o, o + nx, 0.0f);
      for (const std::uint32_t i : active) o[i] = std::min(1.0f, (acc[i] - need[i]) * inv_width);
    }
  });
}

void SampleAtmosphere::liquid_intensity(double z, std::span<float> out) const {
  cloud_intensity(kLiquid, z, liquid_cloud_envelope(z), mean_westerly(z) * time_ / 1000.0,
                  kMeanSoutherly * time_ / 1000.0, out);
}

void SampleAtmosphere::ice_intensity(double z, std::span<float> out) const {
  cloud_intensity(kIce, z, ice_cloud_envelope(z), mean_westerly(z) * time_ / 1000.0,
                  kMeanSoutherly * time_ / 1000.0, out);
}

void SampleAtmosphere::rain_intensity(double z, std::span<float> out) const {
  // Rain falls out of the dense parts of the liquid clouds at kRainSourceHeight; the
  // shafts lag slightly behind in the weaker wind below.
  const double lag_km = 0.8 * (kRainSourceHeight - z) / 1000.0;
  cloud_intensity(kRainSource, kRainSourceHeight, rain_top_envelope(z),
                  mean_westerly(kRainSourceHeight) * time_ / 1000.0 - lag_km,
                  kMeanSoutherly * time_ / 1000.0, out);
}

void SampleAtmosphere::smooth_noise(std::uint64_t salt, double z, std::span<float> out) const {
  const FbmPlane fbm(kSmoothNoise, noise_key(seed_, salt), grid_.x_km, grid_.y_km, z / 1000.0,
                     mean_westerly(z) * time_ / 1000.0, kMeanSoutherly * time_ / 1000.0);
  const std::size_t nx = grid_.dims.x;
  for_rows(grid_.dims.y, [&](std::size_t j) { fbm.row(j, out.subspan(j * nx, nx)); });
}

void SampleAtmosphere::fill_temperature(double z, std::span<float> out) const {
  smooth_noise(kSaltTemperature, z, out);
  const auto t_std = static_cast<float>(standard_temperature(z));
  const std::size_t nx = grid_.dims.x;
  for_rows(grid_.dims.y, [&](std::size_t j) {
    float* o = out.data() + j * nx;
    const float* dt = dt_.data() + j * nx;
    for (std::size_t i = 0; i < nx; ++i) o[i] = t_std + dt[i] + 0.6f * o[i];
  });
}

void SampleAtmosphere::fill_pressure(double z, std::span<float> out) const {
  // Hypsometric equation for a column at standard_temperature(z) + dt: exact for the
  // column part of the temperature (ta adds a small smooth perturbation on top).
  // p / ps depends on the column offset dt only: tabulate it over the dt range of this
  // step (steps of 0.05 K; linear interpolation errs by < 1e-7 relative) instead of a
  // log and an exp per sample.
  constexpr double kStep = 0.05;
  const std::size_t entries = static_cast<std::size_t>(std::ceil((dt_max_ - dt_min_) / kStep)) + 2;
  std::vector<float> ratio(entries);
  for (std::size_t e = 0; e < entries; ++e) {
    const double dt = dt_min_ + kStep * static_cast<double>(e);
    ratio[e] = static_cast<float>(column_pressure(z, 1.0, dt));
  }
  const auto dt_min = static_cast<float>(dt_min_);
  const auto inv_step = static_cast<float>(1.0 / kStep);
  const auto last = static_cast<float>(entries - 2);
  const std::size_t nx = grid_.dims.x;
  for_rows(grid_.dims.y, [&](std::size_t j) {
    float* o = out.data() + j * nx;
    const float* dt = dt_.data() + j * nx;
    const float* ps = ps_.data() + j * nx;
    for (std::size_t i = 0; i < nx; ++i) {
      const float u = std::clamp((dt[i] - dt_min) * inv_step, 0.0f, last);
      const auto e = static_cast<std::size_t>(u);
      const float f = u - static_cast<float>(e);
      o[i] = ps[i] * (ratio[e] + (ratio[e + 1] - ratio[e]) * f);
    }
  });
}

void SampleAtmosphere::fill_wind(bool eastward, double z, std::span<float> out) const {
  smooth_noise(eastward ? kSaltEastward : kSaltNorthward, z, out);
  const auto bl = static_cast<float>(boundary_layer_factor(z));
  const auto core = static_cast<float>(jet_core_speed(z));
  const auto base = static_cast<float>(eastward ? background_westerly(z) : kMeanSoutherly);
  const auto vortex = static_cast<float>(vortex_height_factor(z)) * bl;
  const float* jet = eastward ? jet_.data() : meander_.data();
  const float* vort = eastward ? vortex_u_.data() : vortex_v_.data();
  const std::size_t nx = grid_.dims.x;
  for_rows(grid_.dims.y, [&](std::size_t j) {
    float* o = out.data() + j * nx;
    const std::size_t row = j * nx;
    for (std::size_t i = 0; i < nx; ++i) {
      o[i] = bl * (base + core * jet[row + i]) + vortex * vort[row + i] + 1.2f * o[i];
    }
  });
}

void SampleAtmosphere::fill_vertical_wind(double z, std::span<float> out) const {
  const std::size_t n = grid_.level_size(), nx = grid_.dims.x;
  std::vector<float> liquid(n), ice(n), rain(n);
  liquid_intensity(z, liquid);
  ice_intensity(z, ice);
  rain_intensity(z, rain);
  smooth_noise(kSaltVertical, z, out);
  const auto turbulence = static_cast<float>(0.3 * bump(z, 0.0, 5000.0, 16000.0));
  const auto lifting = static_cast<float>(0.12 * bump(z, 0.0, 4000.0, 11000.0));
  const auto near_ground = static_cast<float>(std::min(1.0, z / 300.0));
  for_rows(grid_.dims.y, [&](std::size_t j) {
    float* o = out.data() + j * nx;
    const std::size_t row = j * nx;
    for (std::size_t i = 0; i < nx; ++i) {
      o[i] = turbulence * o[i] + lifting * band_[row + i] + 2.5f * liquid[row + i] +
             0.6f * ice[row + i] - 0.6f * near_ground * rain[row + i];
    }
  });
}

}  // namespace strielad::synthetic
