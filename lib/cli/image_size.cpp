// SPDX-License-Identifier: Apache-2.0
#include "cli/image_size.h"

#include <regex>

#include "core/error.h"

namespace strielad::cli {

std::pair<int, int> parse_image_size(const std::string& text, std::string_view flag) {
  static const std::regex pattern(R"((\d{1,5})[xX](\d{1,5}))");
  std::smatch m;
  if (!std::regex_match(text, m, pattern)) {
    throw make_error(ErrorCode::kInvalidArgument, "{} {}: expected WIDTHxHEIGHT, e.g. 1280x720",
                     flag, text);
  }
  const int w = std::stoi(m[1]), h = std::stoi(m[2]);
  if (w < 16 || h < 16 || w > 16384 || h > 16384) {
    throw make_error(ErrorCode::kInvalidArgument, "{} {}: each side must be 16 to 16384", flag, text);
  }
  return {w, h};
}

}  // namespace strielad::cli
