// SPDX-License-Identifier: Apache-2.0
#include "cli/step_range.h"

#include <charconv>
#include <string>

#include "core/error.h"

namespace strielad::cli {
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
