// SPDX-License-Identifier: Apache-2.0
// Vertical profiles of the sample atmosphere: the ICAO standard atmosphere, the
// hypsometric pressure that goes with it, the westerly jet, and the height envelopes
// of the cloud species. Heights are metres above ground.
#pragma once

namespace strielad::synthetic {

inline constexpr double kGravity = 9.80665;             // m s-2
inline constexpr double kGasConstantDryAir = 287.053;   // J kg-1 K-1
inline constexpr double kLapseRate = 0.0065;            // K m-1 in the troposphere
inline constexpr double kTropopauseHeight = 11000.0;    // m
inline constexpr double kSurfaceTemperature = 288.15;   // K
inline constexpr double kSurfacePressure = 101325.0;    // Pa
inline constexpr double kHypsometricExponent =
    kGravity / (kGasConstantDryAir * kLapseRate);      // about 5.256

// 288.15 K - 6.5 K/km up to 11 km, isothermal 216.65 K above.
double standard_temperature(double z);

// Pressure at height z in a column whose temperature is standard_temperature(z) + dt
// (dt constant with height) and whose surface pressure is `surface_pressure`.
double column_pressure(double z, double surface_pressure, double dt);

// The inverse of column_pressure: the height (m) where a column with `surface_pressure`
// at z = 0 and offset dt has pressure p.
double column_height(double p, double surface_pressure, double dt);

// Zonal wind of the jet core (m/s) at height z: peak about 35 m/s near 10 km.
double jet_core_speed(double z);
// Zonal background wind away from the jet core (m/s).
double background_westerly(double z);
// Reduction of the wind in the surface layer: about 0.45 at 20 m, 1 above 1 km.
double boundary_layer_factor(double z);
// Strength of the cyclone's circulation relative to the surface.
double vortex_height_factor(double z);
// Area-mean eastward wind: the speed clouds at height z drift with.
double mean_westerly(double z);
inline constexpr double kMeanSoutherly = 2.0;  // m/s, northward drift of everything

// Smooth bump: 0 at or outside (lo, hi), 1 at peak, C1 continuous.
double bump(double z, double lo, double peak, double hi);

// Where each hydrometeor may exist (0 outside, 1 where it is most likely).
double liquid_cloud_envelope(double z);  // 500 .. 6000 m
double ice_cloud_envelope(double z);     // 6000 .. 12000 m
double rain_top_envelope(double z);      // 1 up to 1500 m, 0 from 3500 m
double rain_evaporation(double z);       // 0.6 at the ground .. 1 from 500 m up

}  // namespace strielad::synthetic
