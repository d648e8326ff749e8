// SPDX-License-Identifier: Apache-2.0
#include "synthetic/hash_noise.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace strielad::synthetic {
namespace {

struct AxisCells {
  std::vector<std::uint32_t> cell;  // lattice cell relative to `first`
  std::vector<float> weight;        // quintic-smoothed fraction within the cell
  std::int64_t first = 0;           // lowest lattice index used
  std::size_t count = 0;            // lattice cells spanned (values needed: count + 1)
};

AxisCells axis_cells(std::span<const double> coords, double scale, double offset) {
  AxisCells a;
  a.cell.resize(coords.size());
  a.weight.resize(coords.size());
  std::vector<std::int64_t> absolute(coords.size());
  std::int64_t lo = 0, hi = 0;
  for (std::size_t i = 0; i < coords.size(); ++i) {
    const double u = coords[i] * scale + offset;
    const double f = std::floor(u);
    absolute[i] = static_cast<std::int64_t>(f);
    a.weight[i] = static_cast<float>(quintic(u - f));
    if (i == 0 || absolute[i] < lo) lo = absolute[i];
    if (i == 0 || absolute[i] > hi) hi = absolute[i];
  }
  a.first = lo;
  a.count = coords.empty() ? 0 : static_cast<std::size_t>(hi - lo + 1);
  for (std::size_t i = 0; i < coords.size(); ++i) {
    a.cell[i] = static_cast<std::uint32_t>(absolute[i] - lo);
  }
  return a;
}

}  // namespace

double unit_hash(std::uint64_t key, std::uint64_t index) noexcept {
  return static_cast<double>(mix64(key ^ mix64(index + 0x632be59bd9b4e019ULL)) >> 11) * 0x1.0p-53;
}

float lattice_value(std::uint64_t key, std::int64_t ix, std::int64_t iy, std::int64_t iz) noexcept {
  std::uint64_t h = mix64(key + static_cast<std::uint64_t>(ix) * 0x9e3779b97f4a7c15ULL);
  h = mix64(h + static_cast<std::uint64_t>(iy) * 0xc2b2ae3d27d4eb4fULL);
  h = mix64(h + static_cast<std::uint64_t>(iz) * 0x165667b19e3779f9ULL);
  return static_cast<float>(static_cast<double>(h >> 40) * (2.0 / 16777215.0) - 1.0);
}

NoisePlane::NoisePlane(std::uint64_t key, std::span<const double> x, std::span<const double> y,
                       double scale_x, double scale_y, double offset_u, double offset_v,
                       double w) {
  AxisCells cx = axis_cells(x, scale_x, offset_u);
  AxisCells cy = axis_cells(y, scale_y, offset_v);
  col_cell_ = std::move(cx.cell);
  col_w_ = std::move(cx.weight);
  row_cell_ = std::move(cy.cell);
  row_w_ = std::move(cy.weight);
  stride_ = cx.count + 1;
  const double wf = std::floor(w);
  const auto iz = static_cast<std::int64_t>(wf);
  const auto wz = static_cast<float>(quintic(w - wf));
  values_.resize((cy.count + 1) * stride_);
  for (std::size_t r = 0; r <= cy.count; ++r) {
    const std::int64_t iy = cy.first + static_cast<std::int64_t>(r);
    for (std::size_t c = 0; c <= cx.count; ++c) {
      const std::int64_t ix = cx.first + static_cast<std::int64_t>(c);
      const float a = lattice_value(key, ix, iy, iz);
      const float b = lattice_value(key, ix, iy, iz + 1);
      values_[r * stride_ + c] = a + (b - a) * wz;
    }
  }
}

void NoisePlane::row_coefficients(std::size_t j, float amplitude, float* base,
                                  float* slope) const {
  const float* r0 = values_.data() + row_cell_[j] * stride_;
  const float* r1 = r0 + stride_;
  const float wy = row_w_[j];
  for (std::size_t c = 0; c + 1 < stride_; ++c) {
    const float a = r0[c] + (r1[c] - r0[c]) * wy;
    const float b = r0[c + 1] + (r1[c + 1] - r0[c + 1]) * wy;
    base[c] = amplitude * a;
    slope[c] = amplitude * (b - a);
  }
}

namespace {
// Per-thread scratch for the coefficients of one lattice row.
float* coefficient_scratch(std::size_t n) {
  thread_local std::vector<float> scratch;
  if (scratch.size() < 2 * n) scratch.resize(2 * n);
  return scratch.data();
}
}  // namespace

void NoisePlane::accumulate_row(std::size_t j, float amplitude, std::span<float> acc) const {
  float* base = coefficient_scratch(stride_);
  float* slope = base + stride_;
  row_coefficients(j, amplitude, base, slope);
  const std::uint32_t* __restrict cell = col_cell_.data();
  const float* __restrict w = col_w_.data();
  float* __restrict out = acc.data();
  const std::size_t n = col_cell_.size();
  for (std::size_t i = 0; i < n; ++i) out[i] += base[cell[i]] + slope[cell[i]] * w[i];
}

void NoisePlane::accumulate_columns(std::size_t j, float amplitude,
                                    std::span<const std::uint32_t> columns,
                                    std::span<float> acc) const {
  float* base = coefficient_scratch(stride_);
  float* slope = base + stride_;
  row_coefficients(j, amplitude, base, slope);
  const std::uint32_t* __restrict cell = col_cell_.data();
  const float* __restrict w = col_w_.data();
  float* __restrict out = acc.data();
  for (const std::uint32_t i : columns) out[i] += base[cell[i]] + slope[cell[i]] * w[i];
}

float NoisePlane::at(std::size_t i, std::size_t j) const {
  std::vector<float> acc(col_cell_.size(), 0.0f);
  const auto column = static_cast<std::uint32_t>(i);
  accumulate_columns(j, 1.0f, std::span<const std::uint32_t>(&column, 1), acc);
  return acc[i];
}

void FbmPlane::row(std::size_t j, std::span<float> out) const {
  std::fill(out.begin(), out.end(), 0.0f);
  for (std::size_t o = 0; o < planes_.size(); ++o) planes_[o].accumulate_row(j, amplitude_[o], out);
}

float FbmPlane::at(std::size_t i, std::size_t j) const {
  std::vector<float> acc(planes_.empty() ? 0 : planes_[0].columns(), 0.0f);
  const auto column = static_cast<std::uint32_t>(i);
  for (std::size_t o = 0; o < planes_.size(); ++o) {
    planes_[o].accumulate_columns(j, amplitude_[o], std::span<const std::uint32_t>(&column, 1),
                                  acc);
  }
  return acc[i];
}

FbmPlane::FbmPlane(const FbmParams& params, std::uint64_t key, std::span<const double> x_km,
                   std::span<const double> y_km, double z_km, double shift_x_km,
                   double shift_y_km) {
  if (params.octaves < 1 || params.octaves > kMaxOctaves || !(params.wavelength_km > 0) ||
      !(params.wavelength_z_km > 0) || !(params.stretch_x > 0)) {
    throw make_error(ErrorCode::kInternal, "noise: bad fractal parameters ({} octaves)",
                     params.octaves);
  }
  double amp = 1, total = 0;
  std::array<double, kMaxOctaves> raw{};
  for (int o = 0; o < params.octaves; ++o) {
    raw[static_cast<std::size_t>(o)] = amp;
    total += amp;
    amp *= params.gain;
  }
  double frequency = 1;
  planes_.reserve(static_cast<std::size_t>(params.octaves));
  for (int o = 0; o < params.octaves; ++o) {
    const auto uo = static_cast<std::uint64_t>(o);
    const std::uint64_t okey = mix64(key + uo * 0xa0761d6478bd642fULL);
    // Per-octave offsets decorrelate the lattices of the octaves.
    const double scale_y = frequency / params.wavelength_km;
    const double scale_x = scale_y / params.stretch_x;
    const double off_u = 1000.0 * unit_hash(okey, 1) - shift_x_km * scale_x;
    const double off_v = 1000.0 * unit_hash(okey, 2) - shift_y_km * scale_y;
    const double w = z_km * frequency / params.wavelength_z_km + 1000.0 * unit_hash(okey, 3);
    planes_.emplace_back(okey, x_km, y_km, scale_x, scale_y, off_u, off_v, w);
    frequency *= 2;
  }
  for (int o = params.octaves - 1; o >= 0; --o) {
    const auto so = static_cast<std::size_t>(o);
    amplitude_[so] = static_cast<float>(raw[so] / total);
    remaining_[so] = o + 1 < params.octaves
                         ? remaining_[so + 1] + amplitude_[so + 1]
                         : 0.0f;
  }
}

}  // namespace strielad::synthetic
