// SPDX-License-Identifier: Apache-2.0
// GRIB files for tests, made from ecCodes' sample templates (/usr/share/eccodes/samples)
// with the keys and values a test sets, in the order given (ecCodes recomputes dependent
// keys as each is set: set the grid type before its keys, the sizes before the values).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace strielad::testing {

struct GribFixtureMessage {
  std::string sample;  // template name without ".tmpl", e.g. "regular_ll_pl_grib2"
  // A vector sets a numeric array key ("pv"; set "NV" before it).
  std::vector<std::pair<std::string, std::variant<long, double, std::string, std::vector<double>>>>
      keys;
  std::vector<double> values;  // empty: the template's
};

// Writes the messages one after another. Throws strielad::Error naming the key ecCodes
// refused.
void write_grib_file(const std::filesystem::path& path,
                     const std::vector<GribFixtureMessage>& messages);

}  // namespace strielad::testing
