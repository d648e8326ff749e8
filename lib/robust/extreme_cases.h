// SPDX-License-Identifier: Apache-2.0
// The robustness matrix: every extreme input with the outcome expected of each
// stage (docs/robustness.md explains each row). Grids are small (a few 4-cell bricks,
// two time steps) so that the whole matrix runs in seconds; the huge-grid cases declare
// their size in the NetCDF file without writing data and are refused (or planned) from
// metadata alone.
#pragma once

#include <string_view>
#include <vector>

#include "robust/extreme_case.h"

namespace strielad::robust {

std::vector<ExtremeCase> extreme_cases();

// The case named `name`. \error kNotFound listing the case names.
ExtremeCase extreme_case(std::string_view name);

}  // namespace strielad::robust
