// SPDX-License-Identifier: Apache-2.0
// The real instant a view shows: a time step of the store (plus seconds within the
// step while advecting) as a UTC Julian day, from the CF time axis (geo/cf_time.h).
// The sun and the flight tracks both need it.
#pragma once

#include <cstdint>
#include <optional>

#include "format/manifest.h"

namespace strielad::view {

// Nothing when `step` is not a step of the store or the time axis has no real date
// (units not "<unit> since <date>", or a model calendar such as 360_day).
std::optional<double> step_julian_day(const format::Manifest& manifest, std::uint32_t step,
                                      double seconds_after = 0);

}  // namespace strielad::view
