// SPDX-License-Identifier: Apache-2.0
// The atmosphere of the model-like samples (model_like_files.h) at one time step, over
// the sample terrain: every field is a function of the column and the true height above
// sea level, so values follow the terrain-following levels they are sampled on.
//   temperature: the standard atmosphere in true height plus a column offset (colder to
//     the north, a travelling warm wave) and a heated surface layer;
//   pressure: hypsometric for that column temperature below a sea-level pressure with a
//     travelling cyclone, so the surface pressure is lower over the mountains;
//   cloud water: one blob about 2 km above the ground drifting east, zero elsewhere;
//   specific humidity: decaying with height above the ground;
//   wind: the sheared westerly and jet of the sample plus the cyclone's vortex, weaker
//     near the ground; vertical wind: flow up the slopes plus an updraft in the cloud.
// Pure functions of (seed, grid position, height, time), as in sample_atmosphere.h.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "synthetic/sample_grid.h"

namespace strielad::synthetic {

enum class ModelField { kTemperature, kCloudWater, kSpecificHumidity, kEastward, kNorthward,
                        kUpward, kPressure };

class ModelAtmosphere {
 public:
  // `surface` holds the terrain height (m) of every column of `grid`, x fastest.
  ModelAtmosphere(const SampleGrid& grid, std::span<const float> surface, std::uint64_t seed,
                  double time_seconds);

  // out[c] = field at column c and height z_asl[c] (m above sea level), every column of
  // the grid (x fastest). Runs in parallel over rows.
  void fill(ModelField field, std::span<const double> z_asl, std::span<float> out) const;

  // Surface pressure (Pa) of every column: the pressure at the terrain height.
  std::span<const double> surface_pressure() const { return ps_; }
  // The height (m above sea level) where column c has pressure p (Pa).
  double height_at_pressure(std::size_t c, double p) const;

 private:
  float value(ModelField field, std::size_t c, double z) const;
  double cloud_shape(std::size_t c, double height_above_ground) const;

  const SampleGrid& grid_;
  std::span<const float> surface_;
  double blob_x_km_ = 0, blob_y_km_ = 0;
  // Per column (x fastest): temperature offset (K), sea-level and surface pressure (Pa),
  // the cyclone's wind at the ground (m/s), the jet weight in [0, 1] and the terrain
  // slope (m/m, east and north).
  std::vector<double> dt_, p_sea_, ps_, vortex_u_, vortex_v_, jet_, slope_x_, slope_y_;
};

}  // namespace strielad::synthetic
