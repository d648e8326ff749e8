// SPDX-License-Identifier: Apache-2.0
// A small global store for the globe's tests: longitude 0..357.5, latitude -90..90 every
// 7.5 degrees (48 x 25), heights 0..15 km on 7 levels, one time step at `time_units`'s
// reference date. Variables "height_km" (the sub-volume "height_km <= 2" is a shell round
// the whole Earth) and "clw" (cloud-like blobs, 1e-4 at their cores, between 2 and 9 km
// over the tropics and the mid-latitude storm tracks).
#pragma once

#include <filesystem>
#include <string>

namespace strielad::testing {

// Writes the NetCDF file under `dir` and converts it into `dir / "globe"`; returns the
// store path. `time_units` e.g. "seconds since 2024-06-21 00:00:00" (the sub-solar point
// then near 180 E, 23.4 N). `nx` x `ny`: the grid (longitudes every 360 / nx degrees,
// latitudes from -90 to 90).
std::filesystem::path write_globe_store(const std::filesystem::path& dir,
                                        const std::string& time_units, std::size_t nx = 48,
                                        std::size_t ny = 25, std::size_t nz = 7);

}  // namespace strielad::testing
