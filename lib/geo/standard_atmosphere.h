// SPDX-License-Identifier: Apache-2.0
// The ICAO standard atmosphere (ISO 2533, identical to the U.S. Standard Atmosphere 1976
// up to 86 km) as a map between pressure and height, for placing pressure levels in
// the world frame. Geopotential height is used as height (the two differ by 0.3% at
// 20 km). Above the last tabulated layer (84.852 km, 0.3734 Pa) the atmosphere is
// continued isothermally at that layer's top temperature (186.946 K), so every
// positive pressure has a finite height and every height a positive pressure; below
// sea level (p > 101325 Pa) the first layer's lapse rate is continued.
#pragma once

namespace strielad::geo {

inline constexpr double kSeaLevelPressurePa = 101325.0;

// Height in metres of pressure `pa` (pascals). Decreasing in `pa`; h(101325) = 0.
// Returns NaN for pa <= 0 or NaN (callers reject those first).
double standard_height_m(double pa);

// Pressure in pascals at height `m` metres; the inverse of standard_height_m.
double standard_pressure_pa(double m);

}  // namespace strielad::geo
