// SPDX-License-Identifier: Apache-2.0
// The variables the model-like samples write (lib/synthetic): name, the field of the
// model atmosphere it holds, and its CF attributes. ICON's set also serves the
// curvilinear sample. Internal to lib/synthetic.
#pragma once

#include <array>

#include "synthetic/model_atmosphere.h"

namespace strielad::synthetic {

struct ModelVariable {
  const char* name;
  ModelField field;
  const char* units;
  const char* standard_name;
  const char* long_name;
};

inline constexpr std::array<ModelVariable, 5> kIconVariables{{
    {"temp", ModelField::kTemperature, "K", "air_temperature", "Temperature"},
    {"qc", ModelField::kCloudWater, "kg kg-1", "mass_fraction_of_cloud_liquid_water_in_air",
     "specific cloud water content"},
    {"u", ModelField::kEastward, "m s-1", "eastward_wind", "Zonal wind"},
    {"v", ModelField::kNorthward, "m s-1", "northward_wind", "Meridional wind"},
    {"w", ModelField::kUpward, "m s-1", "upward_air_velocity", "Vertical velocity"},
}};

}  // namespace strielad::synthetic
