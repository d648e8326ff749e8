// SPDX-License-Identifier: Apache-2.0
// Reading netCDF attributes the way CF uses them: text attributes stored as NC_CHAR or
// NC_STRING, numeric attributes (possibly vectors) read exactly. The caller must hold
// netcdf_mutex().
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace strielad::ingest {

bool has_attribute(int grpid, int varid, std::string_view name);

// The attribute's netCDF type, or nullopt when absent.
std::optional<int> attribute_type(int grpid, int varid, std::string_view name);

// A text attribute (NC_CHAR, or NC_STRING with its values joined by spaces), without
// trailing NULs. nullopt when absent or numeric.
std::optional<std::string> text_attribute(int grpid, int varid, std::string_view name);

// Convenience: text_attribute or "".
std::string text_attribute_or_empty(int grpid, int varid, std::string_view name);

// A numeric attribute's values. Integers up to 64 bits are exact (long double has a
// 64-bit mantissa on the platforms we build for). Empty when absent or not numeric.
std::vector<long double> numeric_attribute(int grpid, int varid, std::string_view name);

// Splits a blank-separated attribute value ("clon clat") into words.
std::vector<std::string> split_words(std::string_view text);

}  // namespace strielad::ingest
