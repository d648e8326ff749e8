// SPDX-License-Identifier: Apache-2.0
// Strict reading of a small JSON document (a scene, a camera path) whose errors name the
// document and the JSON path of the offending value ("scene.json: subvolumes[1].limits[0]
// .min: ..."): a repeated key or too deep nesting is rejected while parsing, and every
// value is type-checked before it is read. What differs between formats is a Format.
#pragma once

#include <nlohmann/json.hpp>

#include <fmt/format.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "core/error.h"

namespace strielad::strict_json {

using Json = nlohmann::json;
using Keys = std::span<const std::string_view>;

// A name from the document as it appears in messages: control characters as \xNN, and
// cut after 64 bytes (at a UTF-8 boundary) with "...", so that a hostile key cannot make
// a message huge or rewrite a terminal.
std::string shown(std::string_view name);

// "a.b" / "b" when `parent` is empty (the top level).
std::string key_path(std::string_view parent, std::string_view key);

// "a[3]".
std::string index_path(std::string_view parent, std::size_t index);

// Throws `code` with "what: path: message" ("what: message" for the whole document).
template <typename... Args>
[[noreturn]] void fail(ErrorCode code, std::string_view what, std::string_view path,
                       fmt::format_string<Args...> format, Args&&... args) {
  const std::string message = fmt::format(format, std::forward<Args>(args)...);
  if (path.empty()) throw make_error(code, "{}: {}", what, message);
  throw make_error(code, "{}: {}: {}", what, path, message);
}

// What one format read this way sets; the words go into its messages.
struct Format {
  std::string_view name;       // "... reserved for a later version of the <name> format"
  std::string_view noun;       // "the <noun> has N bytes, more than the limit of M"
  std::string_view file_noun;  // "cannot read: is a directory, not <file_noun>"
  std::uint64_t version = 1;   // the newest format_version this reader reads
  std::size_t max_bytes = 0;
  std::size_t max_nesting = 0;  // levels of objects and arrays
  // "got integer 3" for a JSON integer where another type is expected; false: "got
  // number 3", as for any other number.
  bool integers_apart = true;
};

// Parses `text` (at most format.max_bytes), rejecting a key repeated in one object,
// nesting deeper than format.max_nesting and a number that overflows binary64: all
// kInvalidInput naming `what` and the path.
Json parse(std::string_view text, std::string_view what, const Format& format);

// The text of a file for parse() (kNotFound / kIo naming the path; a directory, or a
// file larger than format.max_bytes, refused without reading it).
std::string read_file(const std::filesystem::path& path, const Format& format);

// Typed access to a parsed document, each error naming the path of the value.
class Reader {
 public:
  Reader(std::string_view what, const Format& format) : what_(what), format_(format) {}

  [[noreturn]] void wrong_type(const Json& v, std::string_view path,
                               std::string_view expected) const;
  void object(const Json& v, std::string_view path) const;
  void array(const Json& v, std::string_view path) const;

  // Rejects keys not in `allowed`, with a distinct message for reserved ones.
  void keys(const Json& obj, std::string_view path, Keys allowed, Keys reserved) const;

  const Json* find(const Json& obj, std::string_view key) const;
  const Json& require(const Json& obj, std::string_view path, std::string_view key) const;

  std::uint64_t integer(const Json& v, std::string_view path, std::uint64_t lo,
                        std::uint64_t hi) const;
  double number(const Json& v, std::string_view path) const;  // finite
  std::string string(const Json& v, std::string_view path) const;

  // Checks the top-level format_version, if any (an integer >= 1): kVersionTooNew when
  // above format.version. Call it before keys() on the root, so that an older reader
  // says "newer" rather than "unknown key".
  void format_version(const Json& root) const;

  std::string_view what() const { return what_; }

 private:
  std::string_view what_;
  Format format_;
};

// parse(), then `read(reader, root)`. A JSON library error escaping `read` is a bug
// (every access is type-checked first): kInternal.
template <typename Read>
auto read_document(std::string_view text, std::string_view what, const Format& format,
                   Read&& read) {
  const Json root = parse(text, what, format);
  try {
    return std::forward<Read>(read)(Reader(what, format), root);
  } catch (const Json::exception& e) {
    fail(ErrorCode::kInternal, what, "", "unexpected JSON error: {}", e.what());
  }
}

}  // namespace strielad::strict_json
