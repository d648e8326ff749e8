// SPDX-License-Identifier: Apache-2.0
// The synthetic atmosphere of the sample dataset at one time step: a standard
// atmosphere with a meridional temperature gradient and a warm sector, hypsometric
// pressure with a travelling cyclone, a sheared westerly jet plus the cyclone's vortex,
// and sparse clouds (liquid, ice, rain) made of thresholded fractal noise organised
// along two frontal bands, drifting with the mean wind.
//
// Every value is a pure function of (seed, x_km, y_km, height, time): the output does
// not depend on the number of threads, and a small grid samples the same atmosphere as
// the full one. Column (2D) fields are computed once per step; a level is then filled
// in parallel over rows.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "synthetic/hash_noise.h"
#include "synthetic/sample_grid.h"
#include "synthetic/sample_variables.h"

namespace strielad::synthetic {

class SampleAtmosphere {
 public:
  SampleAtmosphere(const SampleGrid& grid, std::uint64_t seed, double time_seconds);

  // Writes level k (index into grid.height, 0 = top) of `variable` into `out`
  // (grid.level_size() floats, x fastest). Runs a tbb::parallel_for over rows.
  void fill_level(SampleVariable variable, std::size_t k, std::span<float> out) const;

  double time_seconds() const { return time_; }
  // Weight in [0, 1] of the frontal bands and the cyclone core per column (x fastest):
  // where clouds are most likely.
  std::span<const float> band_weight() const { return band_; }

 private:
  struct CloudSpecies {
    std::uint64_t salt;
    FbmParams noise;
    float threshold;     // of noise + band_gain * band where the envelope is 1
    float band_gain;     // how much the frontal bands favour this species
    float edge_penalty;  // extra threshold where the envelope falls to 0
    float width;         // noise excess over the threshold that gives intensity 1
  };
  static const CloudSpecies kLiquid, kIce, kRainSource;

  // Intensity in [0, 1] of a cloud species evaluated on the plane z_eval (m), exactly 0
  // outside clouds; `envelope` in [0, 1] weights the threshold.
  void cloud_intensity(const CloudSpecies& species, double z_eval, double envelope,
                       double shift_x_km, double shift_y_km, std::span<float> out) const;
  void liquid_intensity(double z, std::span<float> out) const;
  void ice_intensity(double z, std::span<float> out) const;
  void rain_intensity(double z, std::span<float> out) const;
  // Dense smooth perturbation in [-1, 1] for variable stream `salt` at height z.
  void smooth_noise(std::uint64_t salt, double z, std::span<float> out) const;

  void fill_temperature(double z, std::span<float> out) const;
  void fill_pressure(double z, std::span<float> out) const;
  void fill_wind(bool eastward, double z, std::span<float> out) const;
  void fill_vertical_wind(double z, std::span<float> out) const;

  const SampleGrid& grid_;
  std::uint64_t seed_;
  double time_;
  // Column fields (x fastest): frontal band weight in [0, 1], column temperature offset
  // (K), surface pressure (Pa), cyclone wind at the surface (m/s), jet-core weight in
  // [0, 1] and the jet's northward slope times that weight.
  std::vector<float> band_, dt_, ps_, vortex_u_, vortex_v_, jet_, meander_;
  double dt_min_ = 0, dt_max_ = 0;  // range of dt_ (for the pressure table)
};

}  // namespace strielad::synthetic
