// SPDX-License-Identifier: Apache-2.0
// Positions from PROJ's own command-line tool, cs2cs (Debian package proj-bin), so that
// tests check placements against PROJ as its users run it, with the projection written
// out by the test, not against this project's code.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace strielad::testing {

// Whether cs2cs runs here (tests skip without it).
bool have_cs2cs();

// `points` from CRS `from` to CRS `to` (PROJ strings, e.g. "+proj=ob_tran +o_proj=longlat
// +o_lat_p=39.25 +o_lon_p=0 +lon_0=18" to "+proj=longlat"), first two coordinates of
// each output line; degrees in and out for longitude/latitude systems. Nothing when
// cs2cs fails.
std::optional<std::vector<std::array<double, 2>>> cs2cs(
    const std::string& from, const std::string& to, const std::vector<std::array<double, 2>>& points);

// The same with a third coordinate (a height in metres, or ECEF z), e.g. "+proj=longlat
// +datum=WGS84" to "+proj=geocent +datum=WGS84 +units=m".
std::optional<std::vector<std::array<double, 3>>> cs2cs_3d(
    const std::string& from, const std::string& to, const std::vector<std::array<double, 3>>& points);

// The rotated pole of EURO-CORDEX and COSMO (39.25 N, 162 W) as a PROJ string written by
// hand: ob_tran with the pole at o_lat_p, lon_0 = pole longitude + 180.
inline const std::string kEuroCordexRotatedPole =
    "+proj=ob_tran +o_proj=longlat +o_lat_p=39.25 +o_lon_p=0 +lon_0=18";

}  // namespace strielad::testing
