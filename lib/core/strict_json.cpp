// SPDX-License-Identifier: Apache-2.0
// Strict JSON reading with errors naming the JSON path: the parser callback that rejects
// repeated keys and deep nesting, and the typed Reader.
#include "core/strict_json.h"

#include <cmath>
#include <limits>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "core/file_io.h"

namespace strielad::strict_json {

std::string shown(std::string_view name) {
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

std::string key_path(std::string_view parent, std::string_view key) {
  return parent.empty() ? shown(key) : fmt::format("{}.{}", parent, shown(key));
}

std::string index_path(std::string_view parent, std::size_t index) {
  return fmt::format("{}[{}]", parent, index);
}

namespace {

bool contains(Keys list, std::string_view key) {
  for (std::string_view k : list) {
    if (k == key) return true;
  }
  return false;
}

std::string join(Keys list) {
  std::string out;
  for (std::string_view k : list) out += out.empty() ? std::string(k) : fmt::format(", {}", k);
  return out;
}

// A short description of a JSON value for "expected X, got Y" messages.
std::string describe(const Json& v, bool integers_apart) {
  switch (v.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return v.get<bool>() ? "true" : "false";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
      return fmt::format("{} {}", integers_apart ? "integer" : "number", v.dump());
    case Json::value_t::number_float: return fmt::format("number {}", v.dump());
    case Json::value_t::string: {
      const std::string quoted = v.dump(-1, ' ', /*ensure_ascii=*/true);
      if (quoted.size() <= 42) return fmt::format("string {}", quoted);
      return fmt::format("string {}...\"", std::string_view(quoted).substr(0, 40));
    }
    case Json::value_t::array: return fmt::format("an array of {} values", v.size());
    case Json::value_t::object: return "an object";
    default: return v.type_name();
  }
}

// Parser callback: rejects a key repeated in one object and nesting deeper than
// `max_nesting` while parsing, and knows the path of the value being parsed.
class SyntaxGuard {
 public:
  SyntaxGuard(std::string_view what, std::size_t max_nesting)
      : what_(what), max_nesting_(max_nesting) {}

  bool operator()(int /*depth*/, Json::parse_event_t event, Json& parsed) {
    switch (event) {
      case Json::parse_event_t::object_start:
      case Json::parse_event_t::array_start:
        count_element();
        if (frames_.size() >= max_nesting_) {
          fail(ErrorCode::kInvalidInput, what_, path(frames_.size()),
               "objects and arrays nest deeper than {} levels", max_nesting_);
        }
        frames_.push_back(Frame{event == Json::parse_event_t::array_start, 0, {}, {}});
        break;
      case Json::parse_event_t::key: {
        Frame& frame = frames_.back();
        std::string key = parsed.get<std::string>();
        if (!frame.keys.insert(key).second) {
          fail(ErrorCode::kInvalidInput, what_, path(frames_.size() - 1),
               "key '{}' appears twice in one object", shown(key));
        }
        frame.key = std::move(key);
        break;
      }
      case Json::parse_event_t::value: count_element(); break;
      case Json::parse_event_t::object_end:
      case Json::parse_event_t::array_end: frames_.pop_back(); break;
    }
    return true;
  }

  // Path of the value the parser is reading now (for errors raised before its event).
  std::string current_value_path() const {
    if (frames_.empty()) return "";
    const Frame& f = frames_.back();
    const std::string parent = path(frames_.size() - 1);
    return f.array ? index_path(parent, f.count) : key_path(parent, f.key);
  }

 private:
  struct Frame {
    bool array = false;
    std::size_t count = 0;  // arrays: elements seen so far
    std::string key;        // objects: the last key seen
    std::set<std::string> keys;
  };

  void count_element() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().count;
  }

  // Path of the container held by frame `depth` (frames 0..depth-1 name it).
  std::string path(std::size_t depth) const {
    std::string out;
    for (std::size_t i = 0; i < depth; ++i) {
      const Frame& f = frames_[i];
      out = f.array ? index_path(out, f.count - 1) : key_path(out, f.key);
    }
    return out;
  }

  std::string_view what_;
  std::size_t max_nesting_;
  std::vector<Frame> frames_;
};

std::string_view without_exception_id(std::string_view message) {
  // "[json.exception.parse_error.101] parse error at ..." -> "parse error at ..."
  const auto end = message.find("] ");
  return message.starts_with("[json.exception.") && end != std::string_view::npos
             ? message.substr(end + 2)
             : message;
}

[[noreturn]] void too_large(std::string_view what, const Format& format, std::uint64_t size) {
  fail(ErrorCode::kInvalidInput, what, "", "the {} has {} bytes, more than the limit of {}",
       format.noun, size, format.max_bytes);
}

}  // namespace

Json parse(std::string_view text, std::string_view what, const Format& format) {
  if (text.size() > format.max_bytes) too_large(what, format, text.size());
  SyntaxGuard guard(what, format.max_nesting);
  try {
    return Json::parse(text.begin(), text.end(),
                       [&guard](int depth, Json::parse_event_t event, Json& parsed) {
                         return guard(depth, event, parsed);
                       });
  } catch (const Json::out_of_range& e) {  // 406: a number overflows binary64
    fail(ErrorCode::kInvalidInput, what, guard.current_value_path(),
         "is not a finite number: {}", without_exception_id(e.what()));
  } catch (const Json::exception& e) {
    fail(ErrorCode::kInvalidInput, what, "", "not valid JSON: {}", without_exception_id(e.what()));
  }
}

std::string read_file(const std::filesystem::path& path, const Format& format) {
  const ReadOnlyFile file(path);  // kNotFound / kIo naming the path
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    fail(ErrorCode::kIo, path.string(), "", "cannot read: is a directory, not {}",
         format.file_noun);
  }
  if (file.size() > format.max_bytes) too_large(path.string(), format, file.size());
  std::string text(file.size(), '\0');
  file.read_at(0, std::as_writable_bytes(std::span(text)));
  return text;
}

void Reader::wrong_type(const Json& v, std::string_view path, std::string_view expected) const {
  fail(ErrorCode::kInvalidInput, what_, path, "expected {}, got {}", expected,
       describe(v, format_.integers_apart));
}

void Reader::object(const Json& v, std::string_view path) const {
  if (!v.is_object()) wrong_type(v, path, "an object");
}

void Reader::array(const Json& v, std::string_view path) const {
  if (!v.is_array()) wrong_type(v, path, "an array");
}

void Reader::keys(const Json& obj, std::string_view path, Keys allowed, Keys reserved) const {
  for (const auto& [key, value] : obj.items()) {
    if (contains(allowed, key)) continue;
    if (contains(reserved, key)) {
      fail(ErrorCode::kInvalidInput, what_, key_path(path, key),
           "key '{}' is reserved for a later version of the {} format (this reader reads "
           "version {})",
           key, format_.name, format_.version);
    }
    fail(ErrorCode::kInvalidInput, what_, key_path(path, key), "unknown key '{}' (allowed {}: {})",
         shown(key), path.empty() ? "at the top level" : "here", join(allowed));
  }
}

const Json* Reader::find(const Json& obj, std::string_view key) const {
  const auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

const Json& Reader::require(const Json& obj, std::string_view path, std::string_view key) const {
  if (const Json* v = find(obj, key)) return *v;
  fail(ErrorCode::kInvalidInput, what_, path, "missing required key '{}'", key);
}

std::uint64_t Reader::integer(const Json& v, std::string_view path, std::uint64_t lo,
                              std::uint64_t hi) const {
  if (!v.is_number_integer()) wrong_type(v, path, "an integer");
  // nlohmann stores every non-negative integer as unsigned: a signed one is negative.
  if (v.is_number_unsigned()) {
    const auto value = v.get<std::uint64_t>();
    if (value >= lo && value <= hi) return value;
  }
  if (hi == std::numeric_limits<std::uint64_t>::max()) {
    fail(ErrorCode::kInvalidInput, what_, path, "must be an integer >= {}, got {}", lo, v.dump());
  }
  fail(ErrorCode::kInvalidInput, what_, path, "must be an integer in {}..{}, got {}", lo, hi,
       v.dump());
}

double Reader::number(const Json& v, std::string_view path) const {
  if (!v.is_number()) wrong_type(v, path, "a number");
  const double value = v.get<double>();
  if (!std::isfinite(value)) {
    fail(ErrorCode::kInvalidInput, what_, path, "must be a finite number, got {}", value);
  }
  return value;
}

std::string Reader::string(const Json& v, std::string_view path) const {
  if (!v.is_string()) wrong_type(v, path, "a string");
  return v.get<std::string>();
}

void Reader::format_version(const Json& root) const {
  const Json* v = find(root, "format_version");
  if (v == nullptr) return;
  const std::uint64_t version =
      integer(*v, "format_version", 1, std::numeric_limits<std::uint64_t>::max());
  if (version > format_.version) {
    throw make_error(ErrorCode::kVersionTooNew,
                     "{}: format_version {} is newer than this reader (max {})", what_, version,
                     format_.version);
  }
}

}  // namespace strielad::strict_json
