// SPDX-License-Identifier: Apache-2.0
// The messages of a GRIB file (edition 1 or 2, mixed, with WMO headers between them), as
// ecCodes reads them: where each one is and what it holds.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ingest/eccodes_call.h"

namespace strielad::ingest {

struct GribMessageSummary {
  std::uint64_t offset = 0;  // of "GRIB" in the file
  std::uint64_t size = 0;    // bytes, "GRIB" to "7777"
  long edition = 0;
  std::string short_name;     // ecCodes' shortName ("t", "gh"; "unknown" when not in its tables)
  std::string type_of_level;  // "isobaricInhPa", "hybrid", "surface" ...
  long level = 0;             // ecCodes' level: whole units, rounded
  double level_value = 0;     // exact (GRIB 2: scaled value and factor), in the level type's
                              // units (hPa for isobaricInhPa, Pa, m, a level number)
  std::string grid_type;      // "regular_ll", "lambert", "reduced_gg" ...
  std::string name, units;    // ecCodes' name ("Temperature") and units ("K")
  std::string grid_md5;       // md5GridSection: equal for messages on one grid
  long validity_date = 0;     // YYYYMMDD
  long validity_time = 0;     // HHMM
  long number_of_values = 0;
  // The vertical coordinate parameters (key "pv": hybrid levels' a then b), when the
  // message has them: how many, and checksum64 of their float64 bytes.
  std::size_t pv_size = 0;
  std::uint64_t pv_checksum = 0;
};

// Every message, in file order. \error kNotFound, kIo; kInvalidInput naming the file, the
// message's number and byte offset and what ecCodes said, for a message it cannot decode
// (a truncated one, a GRIB 1 grid without its description section ...).
std::vector<GribMessageSummary> list_grib_messages(const std::filesystem::path& path);

// A message's bytes, decoded. The caller holds eccodes_mutex() while it uses the handle.
// \error kInvalidInput naming `what` and what ecCodes said.
GribHandle decode_grib_message(std::span<const std::byte> bytes, std::string_view what);

// The message `summary` (from list_grib_messages) of `path`, read and decoded; the caller
// holds eccodes_mutex(). \error kIo, kTruncated, kInvalidInput.
GribHandle read_grib_message(const std::filesystem::path& path, const GribMessageSummary& summary);

}  // namespace strielad::ingest
