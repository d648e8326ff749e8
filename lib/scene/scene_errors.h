// SPDX-License-Identifier: Apache-2.0
// Internal to lib/scene: errors that name the scene and the path of the offending value
// ("scene.json: subvolumes[1].limits[0].min: ..."), and path building.
#pragma once

#include <fmt/format.h>

#include <cstddef>
#include <string>
#include <string_view>

#include "core/error.h"

namespace strielad::scene_detail {

// A name from the scene as it appears in messages: control characters as \xNN, and cut
// after 64 bytes (at a UTF-8 boundary) with "...", so that a hostile key cannot make a
// message huge or rewrite a terminal.
inline std::string shown(std::string_view name) {
  constexpr std::size_t kMaxShown = 64;
  std::size_t n = name.size();
  if (n > kMaxShown) {
    n = kMaxShown;
    while (n > 0 && (static_cast<unsigned char>(name[n]) & 0xC0) == 0x80) --n;
  }
  std::string out;
  for (const char c : name.substr(0, n)) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7F) {
      out += fmt::format("\\x{:02x}", u);
    } else {
      out += c;
    }
  }
  if (n < name.size()) out += "...";
  return out;
}

// "a.b" / "b" when `parent` is empty (the top level).
inline std::string key_path(std::string_view parent, std::string_view key) {
  return parent.empty() ? shown(key) : fmt::format("{}.{}", parent, shown(key));
}

inline std::string index_path(std::string_view parent, std::size_t index) {
  return fmt::format("{}[{}]", parent, index);
}

// Throws `code` with "what: path: message" ("what: message" for the whole scene).
template <typename... Args>
[[noreturn]] void fail(ErrorCode code, std::string_view what, std::string_view path,
                       fmt::format_string<Args...> format, Args&&... args) {
  const std::string message = fmt::format(format, std::forward<Args>(args)...);
  if (path.empty()) throw make_error(code, "{}: {}", what, message);
  throw make_error(code, "{}: {}: {}", what, path, message);
}

}  // namespace strielad::scene_detail
