// SPDX-License-Identifier: Apache-2.0
// Parsing of the command-line spellings used by `strielad-sample`, kept here so
// that they are testable without the tool.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "grid/axis.h"
#include "synthetic/model_like_files.h"

namespace strielad::synthetic {

// "1429x1556x150" (also 'X') -> Dims3{1429, 1556, 150}. Throws kInvalidArgument quoting
// the text when it is not three positive decimal integers.
Dims3 parse_dims(std::string_view text);

// A non-negative decimal integer for flag `what` (e.g. "--steps"). Unlike CLI11's
// unsigned options it rejects "-1" instead of wrapping it to 2^64 - 1. Throws
// kInvalidArgument naming the flag and the text.
std::uint64_t parse_unsigned(std::string_view text, std::string_view what);

// "clw,ta, ua" -> {"clw", "ta", "ua"}. Names are checked against the known variables;
// throws kInvalidArgument on an empty list, an empty item or an unknown name.
std::vector<std::string> parse_variable_list(std::string_view text);

// "sample" (default), "icon", "icon-cf", "sigma-pressure" or "wrf" (--model). Throws
// kInvalidArgument quoting the text and listing the names.
SampleModel parse_sample_model(std::string_view text);

}  // namespace strielad::synthetic
