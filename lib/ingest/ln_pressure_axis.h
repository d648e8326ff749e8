// SPDX-License-Identifier: Apache-2.0
// CF atmosphere_ln_pressure_coordinate (CF conventions, appendix D): p(k) = p0 * exp(-lev(k)),
// formula_terms "p0: var lev: var". The pressure depends on the level alone, not on the
// column or the time step, so the z axis becomes a plain pressure axis in Pa (the levels
// known exactly, placed like any pressure-level input) rather than a per-sample geometry
// field as the other formulas (vertical_geometry_detection.h) need.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "grid/axis.h"

namespace strielad::ingest {

inline constexpr std::string_view kLnPressureCoordinate = "atmosphere_ln_pressure_coordinate";

// p0_pa * exp(-lev[k]) for every k. Pure.
// \error kInvalidInput naming `context`: p0 not finite or not positive; a lev value not
// finite; a pressure that is not a positive finite number (exp overflows or underflows);
// pressures not strictly monotonic in k (lev not strictly monotonic, or two levels so
// close that their pressures are equal in double).
std::vector<double> ln_pressure_levels(double p0_pa, std::span<const double> lev,
                                       std::string_view context);

// The pressure axis of coordinate variable `varid` in group `grpid` (standard_name
// atmosphere_ln_pressure_coordinate, with formula_terms): named like the coordinate,
// kind pressure, units Pa, standard_name air_pressure, positive down. The term variables
// are looked up in the coordinate's group, then its ancestors. Caller holds
// netcdf_mutex(). `file` names the file in messages.
// \error kInvalidInput naming the file, coordinate and term: formula_terms malformed or
// without a p0 or lev term; a term variable the file lacks; p0 not a scalar or not in a
// pressure unit (no units: Pa, as for the other formulas); lev not on the coordinate's
// dimension; what ln_pressure_levels refuses.
Axis read_ln_pressure_axis(int grpid, int varid, const std::string& file);

}  // namespace strielad::ingest
