// SPDX-License-Identifier: Apache-2.0
// Reading the fields of the manifest's JSON objects (the manifest itself, its codec and
// geometry records): typed access to a required key, and the store's 64-bit checksums
// as 16 lowercase hex digits, with errors (kCorrupt) naming the object and the key.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/error.h"

namespace strielad::format::json_fields {

template <typename T>
T get(const nlohmann::json& j, std::string_view key, std::string_view where) {
  const auto it = j.find(std::string(key));
  if (it == j.end()) throw make_error(ErrorCode::kCorrupt, "{}: missing key '{}'", where, key);
  try {
    return it->get<T>();
  } catch (const nlohmann::json::exception& e) {
    throw make_error(ErrorCode::kCorrupt, "{}: key '{}' has the wrong type: {}", where, key,
                     e.what());
  }
}

inline std::string hex64(std::uint64_t v) { return fmt::format("{:016x}", v); }

inline std::uint64_t parse_hex64(const std::string& s, std::string_view key,
                                 std::string_view where) {
  if (s.size() != 16 || s.find_first_not_of("0123456789abcdef") != std::string::npos) {
    throw make_error(ErrorCode::kCorrupt, "{}: key '{}' must be 16 lowercase hex digits, got '{}'",
                     where, key, s);
  }
  return std::stoull(s, nullptr, 16);
}

}  // namespace strielad::format::json_fields
