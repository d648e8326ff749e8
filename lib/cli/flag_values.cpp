// SPDX-License-Identifier: Apache-2.0
// Parsers of flag values shared by the tools: image sizes (cli/image_size.h) and step
// ranges (cli/step_range.h).
#include "cli/image_size.h"
#include "cli/step_range.h"

#include <charconv>
#include <regex>
#include <string>

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

namespace {

std::optional<std::uint32_t> parse_index(std::string_view s, std::string_view text,
                                         std::string_view flag) {
  if (s.empty()) return std::nullopt;
  std::uint32_t v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc{} || end != s.data() + s.size()) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "{} '{}': '{}' is not a step index (expected A:B, A:, :B or A)", flag, text, s);
  }
  return v;
}

}  // namespace

StepRange parse_step_range(std::string_view text, std::string_view flag) {
  StepRange r;
  const auto colon = text.find(':');
  if (colon == std::string_view::npos) {
    r.first = r.last = parse_index(text, text, flag);
    if (!r.first) throw make_error(ErrorCode::kInvalidArgument, "{} is empty", flag);
    return r;
  }
  r.first = parse_index(text.substr(0, colon), text, flag);
  r.last = parse_index(text.substr(colon + 1), text, flag);
  if (r.first && r.last && *r.first > *r.last) {
    throw make_error(ErrorCode::kInvalidArgument, "{} '{}': first step is after the last", flag,
                     text);
  }
  return r;
}

}  // namespace strielad::cli
