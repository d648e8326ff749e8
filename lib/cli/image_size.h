// SPDX-License-Identifier: Apache-2.0
// The WIDTHxHEIGHT flag of the tools that render (strielad-view, strielad-bench view).
#pragma once

#include <string>
#include <string_view>
#include <utility>

namespace strielad::cli {

// "1280x720" (or "1280X720") -> {1280, 720}; each side 16 to 16384.
// \error kInvalidArgument naming `flag` and the text.
std::pair<int, int> parse_image_size(const std::string& text, std::string_view flag = "--size");

}  // namespace strielad::cli
