// SPDX-License-Identifier: Apache-2.0
// Internal to lib/lod's camera paths: errors "what: path: message" naming the file and
// the JSON path of the offending value, and path building.
#pragma once

#include <fmt/format.h>

#include <cstddef>
#include <string>
#include <string_view>

#include "core/error.h"

namespace strielad::lod::path_detail {

// A key as shown in messages: control characters as \xNN, at most 64 bytes (cut at a
// UTF-8 boundary, then "..."), so a hostile key cannot make a message huge.
inline std::string shown(std::string_view key) {
  constexpr std::size_t kMaxShown = 64;
  std::size_t n = key.size();
  if (n > kMaxShown) {
    n = kMaxShown;
    while (n > 0 && (static_cast<unsigned char>(key[n]) & 0xC0) == 0x80) --n;
  }
  std::string out;
  for (const char c : key.substr(0, n)) {
    const auto u = static_cast<unsigned char>(c);
    out += (u < 0x20 || u == 0x7F) ? fmt::format("\\x{:02x}", u) : std::string(1, c);
  }
  if (n < key.size()) out += "...";
  return out;
}

inline std::string key_path(std::string_view parent, std::string_view key) {
  return parent.empty() ? shown(key) : fmt::format("{}.{}", parent, shown(key));
}

inline std::string index_path(std::string_view parent, std::size_t index) {
  return fmt::format("{}[{}]", parent, index);
}

template <typename... Args>
[[noreturn]] void fail(ErrorCode code, std::string_view what, std::string_view path,
                       fmt::format_string<Args...> format, Args&&... args) {
  const std::string message = fmt::format(format, std::forward<Args>(args)...);
  if (path.empty()) throw make_error(code, "{}: {}", what, message);
  throw make_error(code, "{}: {}: {}", what, path, message);
}

}  // namespace strielad::lod::path_detail
