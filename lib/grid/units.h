// SPDX-License-Identifier: Apache-2.0
// The units of coordinate axes the tools convert between: lengths, pressures and angles
// as CF files write them (case and surrounding blanks ignored).
#pragma once

#include <optional>
#include <string_view>

namespace strielad {

// Metres per unit: m, metre(s), meter(s) -> 1; km, kilometre(s), kilometer(s) -> 1000.
std::optional<double> metres_per_length_unit(std::string_view units);

// Pascals per unit: Pa, hPa, mbar, millibar(s), mb, kPa, bar(s), atm.
std::optional<double> pascals_per_pressure_unit(std::string_view units);

// degrees, degree, deg and the CF forms degrees_east, degrees_north (and singular).
bool is_degree_units(std::string_view units);

}  // namespace strielad
