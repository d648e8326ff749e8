// SPDX-License-Identifier: Apache-2.0
#include "synthetic/sample_variables.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <array>

#include "core/error.h"

namespace strielad::synthetic {
namespace {

constexpr std::array<SampleVariableInfo, 8> kVariables{{
    {SampleVariable::kClw, "clw", "kg kg-1", "specific cloud liquid water content",
     "mass_fraction_of_cloud_liquid_water_in_air", true},
    {SampleVariable::kCli, "cli", "kg kg-1", "specific cloud ice content",
     "mass_fraction_of_cloud_ice_in_air", true},
    {SampleVariable::kQr, "qr", "kg kg-1", "rain mixing ratio", "mass_fraction_of_rain_in_air",
     true},
    {SampleVariable::kTa, "ta", "K", "air temperature", "air_temperature", false},
    {SampleVariable::kPres, "pres", "Pa", "air pressure", "air_pressure", false},
    {SampleVariable::kUa, "ua", "m s-1", "eastward wind", "eastward_wind", false},
    {SampleVariable::kVa, "va", "m s-1", "northward wind", "northward_wind", false},
    {SampleVariable::kWa, "wa", "m s-1", "upward air velocity", "upward_air_velocity", false},
}};

}  // namespace

std::span<const SampleVariableInfo> sample_variable_table() noexcept { return kVariables; }

const SampleVariableInfo& sample_variable_info(SampleVariable variable) noexcept {
  return kVariables[static_cast<std::size_t>(variable)];
}

SampleVariable sample_variable_from_name(std::string_view name) {
  for (const auto& info : kVariables) {
    if (info.name == name) return info.id;
  }
  throw make_error(ErrorCode::kInvalidArgument,
                   "unknown sample variable '{}' (known variables: {})", name,
                   fmt::join(all_sample_variable_names(), ", "));
}

std::vector<std::string> all_sample_variable_names() {
  std::vector<std::string> names;
  for (const auto& info : kVariables) names.emplace_back(info.name);
  return names;
}

}  // namespace strielad::synthetic
