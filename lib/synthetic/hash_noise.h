// SPDX-License-Identifier: Apache-2.0
// Deterministic noise for the sample generator: an integer hash (no <random>
// distributions, whose output differs between standard libraries), lattice value noise
// with quintic interpolation, and fractal sums of it. Noise is evaluated one horizontal
// plane at a time: the lattice of a plane is blended in z once, after which a grid point
// costs four table reads per octave. Results depend only on the key and coordinates,
// never on threads or evaluation order.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace strielad::synthetic {

// splitmix64 finaliser: a bijective 64-bit mix.
constexpr std::uint64_t mix64(std::uint64_t z) noexcept {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// A key for one independent noise stream of a seed ("salt" names the stream).
constexpr std::uint64_t noise_key(std::uint64_t seed, std::uint64_t salt) noexcept {
  return mix64(mix64(seed + 0x9e3779b97f4a7c15ULL) ^ (salt * 0xd1b54a32d192ed03ULL));
}

// Uniform in [0, 1) for (key, index).
double unit_hash(std::uint64_t key, std::uint64_t index) noexcept;

// Uniform in [-1, 1] at an integer lattice point.
float lattice_value(std::uint64_t key, std::int64_t ix, std::int64_t iy, std::int64_t iz) noexcept;

// 6t^5 - 15t^4 + 10t^3: zero first and second derivative at 0 and 1.
constexpr double quintic(double t) noexcept { return t * t * t * (t * (t * 6 - 15) + 10); }

// One octave of value noise on the plane w = const, sampled at lattice coordinates
// u_i = x[i] * scale_x + offset_u, v_j = y[j] * scale_y + offset_v.
class NoisePlane {
 public:
  NoisePlane(std::uint64_t key, std::span<const double> x, std::span<const double> y,
             double scale_x, double scale_y, double offset_u, double offset_v, double w);

  std::size_t columns() const noexcept { return col_cell_.size(); }
  std::size_t rows() const noexcept { return row_cell_.size(); }

  // acc[i] += amplitude * noise(i, j) for every column i (acc.size() == columns()).
  void accumulate_row(std::size_t j, float amplitude, std::span<float> acc) const;
  // The same for the listed columns only.
  void accumulate_columns(std::size_t j, float amplitude,
                          std::span<const std::uint32_t> columns, std::span<float> acc) const;
  // One value (for tests and spot checks; the row functions give identical results).
  float at(std::size_t i, std::size_t j) const;

 private:
  // Per lattice cell c of row j: noise = base[c] + slope[c] * col_w, scaled by amplitude.
  void row_coefficients(std::size_t j, float amplitude, float* base, float* slope) const;

  std::vector<float> values_;  // (lattice rows) x stride values, blended in w
  std::size_t stride_ = 0;
  std::vector<std::uint32_t> col_cell_, row_cell_;
  std::vector<float> col_w_, row_w_;
};

struct FbmParams {
  double wavelength_km = 50;    // horizontal wavelength of the first octave
  double wavelength_z_km = 2;   // vertical wavelength of the first octave
  int octaves = 4;              // at most kMaxOctaves
  double gain = 0.5;            // amplitude ratio between octaves
  double stretch_x = 1;         // x wavelength / y wavelength (> 1: streaks along x)
};

inline constexpr int kMaxOctaves = 6;

// Fractal sum of value noise on one horizontal plane at height z_km, with the pattern
// displaced by (shift_x_km, shift_y_km) (advection). Amplitudes are normalised to sum 1,
// so values lie in [-1, 1]. Octaves are always added in order 0, 1, ..., so every way
// of evaluating gives bit-identical values.
class FbmPlane {
 public:
  FbmPlane(const FbmParams& params, std::uint64_t key, std::span<const double> x_km,
           std::span<const double> y_km, double z_km, double shift_x_km = 0,
           double shift_y_km = 0);

  int octaves() const noexcept { return static_cast<int>(planes_.size()); }
  float amplitude(int o) const noexcept { return amplitude_[static_cast<std::size_t>(o)]; }
  // Sum of the amplitudes of octaves o+1 .. last: the most the rest can add or take.
  float remaining(int o) const noexcept { return remaining_[static_cast<std::size_t>(o)]; }
  const NoisePlane& octave(int o) const noexcept { return planes_[static_cast<std::size_t>(o)]; }

  // out[i] = fbm(i, j) for every column i.
  void row(std::size_t j, std::span<float> out) const;
  float at(std::size_t i, std::size_t j) const;

 private:
  std::vector<NoisePlane> planes_;
  std::array<float, kMaxOctaves> amplitude_{};
  std::array<float, kMaxOctaves> remaining_{};
};

}  // namespace strielad::synthetic
