// SPDX-License-Identifier: Apache-2.0
// The terrain-following vertical coordinates of the model-like samples, top to bottom
// as ICON and IFS number their levels (index 0 is the highest level):
//   hybrid height (ICON, CF atmosphere_hybrid_height_coordinate): z = a + b * orog, the
//     nominal heights a stretched like the sample's height axis and b a SLEVE-like decay
//     from 1 at the ground to 0 at the model top, so the top is flat;
//   hybrid sigma-pressure (IFS, CAM; CF atmosphere_hybrid_sigma_pressure_coordinate):
//     p = ap + b * ps, pure pressure at the top and terrain-following near the ground.
#pragma once

#include <cstddef>
#include <vector>

namespace strielad::synthetic {

// e-folding height (m) of the terrain's imprint on the hybrid height levels: small
// enough that the levels flatten well below the top, large enough that they stay
// strictly ordered over the highest sample mountains (about 4.5 km).
inline constexpr double kSleveDecayHeight = 8000.0;
// The nominal surface pressure of the hybrid sigma-pressure coefficients (Pa).
inline constexpr double kHybridReferencePressure = 101325.0;

struct HybridHeightLevels {
  std::vector<double> half_a, half_b;  // nz + 1 half levels: a in m above the surface
  std::vector<double> full_a, full_b;  // nz full levels, midway between the half levels
};

// nz >= 1 levels from kModelTop (half level 0) down to the surface (half level nz,
// a = 0, b = 1). A full level's height is the mean of its two half levels' heights.
HybridHeightLevels hybrid_height_levels(std::size_t nz);

struct HybridPressureLevels {
  std::vector<double> half_ap, half_b;  // nz + 1 half levels, ap in Pa
  std::vector<double> full_ap, full_b;  // nz full levels, the means of their half levels
};

// nz >= 1 levels from the pressure of the standard atmosphere at kModelTop (half level 0,
// b = 0) down to the surface (half level nz: ap = 0, b = 1). Pressure grows strictly
// downwards in every column whose surface pressure is above 40 kPa.
HybridPressureLevels hybrid_pressure_levels(std::size_t nz);

}  // namespace strielad::synthetic
