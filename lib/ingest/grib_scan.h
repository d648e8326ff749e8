// SPDX-License-Identifier: Apache-2.0
// The 3-D fields of a GRIB file: its messages grouped into variables by (shortName,
// typeOfLevel), each variable's levels sorted into a vertical axis, and its validity
// times into steps, with every (step, level) found exactly once.
// Vertical level types: isobaricInhPa and isobaricInPa (pressure), heightAboveGround and
// heightAboveSea (height in metres), hybrid, generalVertical and generalVerticalLayer
// (model levels). Fields on one level, on other layers (pressureFromGroundLayer ...) or on
// other level types are not 3-D fields: they are listed as skipped, with why; those on one
// level (surface pressure, orography) are also kept as planes, for placing the levels.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "grid/axis.h"
#include "ingest/grib_messages.h"

namespace strielad::ingest {

struct GribVariable {
  std::string short_name, name, units, type_of_level;
  Axis z;                           // the levels, ascending (pressure: 1000 hPa last)
  std::vector<std::int64_t> times;  // validity times, seconds since 1970-01-01, ascending
  std::string grid_md5;             // every message of it is on this grid
  // messages[t][k]: the message at times[t], z.values[k].
  std::vector<std::vector<GribMessageSummary>> messages;
};

struct GribSkipped {
  std::string short_name, type_of_level, why;
};

struct GribScan {
  std::filesystem::path path;
  std::vector<GribVariable> variables;  // in the order of their first message
  std::vector<GribSkipped> skipped;
  // Fields on one level of any type (lnsp on hybrid level 1, sp or orog on the surface),
  // as one-level variables; those whose messages clash (two grids, a step twice) are
  // only skipped.
  std::vector<GribVariable> planes;
};

// \error what list_grib_messages throws; kInvalidInput naming the file, the variable and
// both byte offsets for a (variable, level, time) found twice, naming the (level, time)
// that is missing when a variable's levels differ between its times, and naming the two
// grids when one variable's messages lie on different grids.
GribScan scan_grib_file(const std::filesystem::path& path);

// Validity date (YYYYMMDD) and time (HHMM) as seconds since 1970-01-01 00:00 UTC.
std::int64_t grib_validity_seconds(long date, long time);

}  // namespace strielad::ingest
