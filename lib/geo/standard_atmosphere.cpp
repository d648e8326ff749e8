// SPDX-License-Identifier: Apache-2.0
#include "geo/standard_atmosphere.h"

#include <array>
#include <cmath>
#include <limits>

namespace strielad::geo {
namespace {

// g0 M / R* in K/m (g0 = 9.80665 m/s^2, M = 0.0289644 kg/mol, R* = 8.31432 J/(mol K)).
constexpr double kGmr = 9.80665 * 0.0289644 / 8.31432;

struct Layer {
  double base_m;   // geopotential height of the layer's base
  double lapse;    // dT/dh in K/m
  double base_t;   // temperature at the base, K
  double base_pa;  // pressure at the base, computed below
};

// ISO 2533 layers (base height, lapse rate, base temperature), then the isothermal
// continuation above 84.852 km at the last layer's top temperature.
std::array<Layer, 8> make_layers() {
  std::array<Layer, 8> l{{{0, -0.0065, 288.15, 0},
                          {11000, 0, 216.65, 0},
                          {20000, 0.001, 216.65, 0},
                          {32000, 0.0028, 228.65, 0},
                          {47000, 0, 270.65, 0},
                          {51000, -0.0028, 270.65, 0},
                          {71000, -0.002, 214.65, 0},
                          {84852, 0, 214.65 - 0.002 * (84852 - 71000), 0}}};
  l[0].base_pa = kSeaLevelPressurePa;
  for (std::size_t i = 1; i < l.size(); ++i) {
    const Layer& b = l[i - 1];
    const double dh = l[i].base_m - b.base_m;
    l[i].base_pa = b.lapse == 0 ? b.base_pa * std::exp(-kGmr * dh / b.base_t)
                                : b.base_pa * std::pow(b.base_t / (b.base_t + b.lapse * dh),
                                                       kGmr / b.lapse);
  }
  return l;
}

const std::array<Layer, 8>& layers() {
  static const std::array<Layer, 8> l = make_layers();
  return l;
}

}  // namespace

double standard_height_m(double pa) {
  if (!(pa > 0)) return std::numeric_limits<double>::quiet_NaN();
  const auto& l = layers();
  std::size_t i = 0;
  while (i + 1 < l.size() && pa <= l[i + 1].base_pa) ++i;
  const Layer& b = l[i];
  if (b.lapse == 0) return b.base_m + b.base_t / kGmr * std::log(b.base_pa / pa);
  return b.base_m + b.base_t / b.lapse * (std::pow(pa / b.base_pa, -b.lapse / kGmr) - 1.0);
}

double standard_pressure_pa(double m) {
  if (std::isnan(m)) return m;
  const auto& l = layers();
  std::size_t i = 0;
  while (i + 1 < l.size() && m >= l[i + 1].base_m) ++i;
  const Layer& b = l[i];
  const double dh = m - b.base_m;
  if (b.lapse == 0) return b.base_pa * std::exp(-kGmr * dh / b.base_t);
  return b.base_pa * std::pow(b.base_t / (b.base_t + b.lapse * dh), kGmr / b.lapse);
}

}  // namespace strielad::geo
