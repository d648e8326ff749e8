// SPDX-License-Identifier: Apache-2.0
#include "synthetic/atmosphere_profiles.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace strielad::synthetic {

double standard_temperature(double z) {
  return kSurfaceTemperature - kLapseRate * std::min(z, kTropopauseHeight);
}

double column_pressure(double z, double surface_pressure, double dt) {
  const double ts = kSurfaceTemperature + dt;
  const double zt = std::min(z, kTropopauseHeight);
  double p = surface_pressure * std::pow((ts - kLapseRate * zt) / ts, kHypsometricExponent);
  if (z > kTropopauseHeight) {
    const double t11 = ts - kLapseRate * kTropopauseHeight;
    p *= std::exp(-kGravity * (z - kTropopauseHeight) / (kGasConstantDryAir * t11));
  }
  return p;
}

double column_height(double p, double surface_pressure, double dt) {
  const double ts = kSurfaceTemperature + dt;
  const double p11 = column_pressure(kTropopauseHeight, surface_pressure, dt);
  if (p >= p11) {
    return ts / kLapseRate * (1.0 - std::pow(p / surface_pressure, 1.0 / kHypsometricExponent));
  }
  const double t11 = ts - kLapseRate * kTropopauseHeight;
  return kTropopauseHeight + kGasConstantDryAir * t11 / kGravity * std::log(p11 / p);
}

double jet_core_speed(double z) {
  const double d = (z - 10000.0) / 4000.0;
  return 30.0 * std::exp(-d * d);
}

double background_westerly(double z) {
  // 5 m/s near the ground growing to about 12 m/s at the tropopause, weaker above.
  const double zk = z / 1000.0;
  return zk < 11.0 ? 5.0 + 0.65 * zk : 12.15 - 0.5 * (zk - 11.0);
}

double boundary_layer_factor(double z) {
  if (z >= 1000.0) return 1.0;
  return 0.3 + 0.7 * std::sqrt(std::max(z, 0.0) / 1000.0);
}

double vortex_height_factor(double z) { return 0.35 + 0.65 * std::exp(-z / 6000.0); }

double mean_westerly(double z) {
  return boundary_layer_factor(z) * (background_westerly(z) + 0.5 * jet_core_speed(z));
}

double bump(double z, double lo, double peak, double hi) {
  if (z <= lo || z >= hi) return 0.0;
  const double t = z < peak ? (z - lo) / (peak - lo) : (hi - z) / (hi - peak);
  const double s = std::sin(0.5 * std::numbers::pi * t);
  return s * s;
}

double liquid_cloud_envelope(double z) { return bump(z, 500.0, 2200.0, 6000.0); }

double ice_cloud_envelope(double z) { return bump(z, 6000.0, 9000.0, 12000.0); }

double rain_top_envelope(double z) { return z <= 1500.0 ? 1.0 : bump(z, 0.0, 1500.0, 3500.0); }

double rain_evaporation(double z) { return 0.6 + 0.4 * std::clamp(z / 500.0, 0.0, 1.0); }

}  // namespace strielad::synthetic
