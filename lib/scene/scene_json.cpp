// SPDX-License-Identifier: Apache-2.0
// Scene JSON: parsing with key, type and syntax checks (duplicate keys, nesting) that
// name the offending path; the canonical writer; reading a scene file.
#include <cmath>
#include <array>
#include <limits>
#include <set>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/file_io.h"
#include "scene/scene.h"
#include "scene/scene_errors.h"

namespace strielad {
namespace {

using nlohmann::json;
using scene_detail::fail;
using scene_detail::index_path;
using scene_detail::key_path;

using Keys = std::span<const std::string_view>;
constexpr std::array<std::string_view, 4> kSceneKeys = {"format_version", "time", "subvolumes",
                                                        "attributes"};
// Reserved for later versions (formats/scene.md, "Extending the format").
constexpr std::array<std::string_view, 6> kReservedSceneKeys = {
    "slices", "trajectories", "terrain", "sun", "advection", "camera"};
constexpr std::array<std::string_view, 4> kSubVolumeKeys = {"id", "name", "limits", "domain"};
constexpr std::array<std::string_view, 1> kReservedSubVolumeKeys = {"style"};
constexpr std::array<std::string_view, 3> kLimitKeys = {"var", "min", "max"};

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
std::string describe(const json& v) {
  switch (v.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return v.get<bool>() ? "true" : "false";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned: return fmt::format("integer {}", v.dump());
    case json::value_t::number_float: return fmt::format("number {}", v.dump());
    case json::value_t::string: {
      const std::string quoted = v.dump(-1, ' ', /*ensure_ascii=*/true);
      if (quoted.size() <= 42) return fmt::format("string {}", quoted);
      return fmt::format("string {}...\"", std::string_view(quoted).substr(0, 40));
    }
    case json::value_t::array: return fmt::format("an array of {} values", v.size());
    case json::value_t::object: return "an object";
    default: return v.type_name();
  }
}

// Parser callback: rejects a key repeated in one object and nesting deeper than
// kMaxSceneNesting while parsing, and knows the path of the value being parsed.
class SyntaxGuard {
 public:
  explicit SyntaxGuard(std::string_view what) : what_(what) {}

  bool operator()(int /*depth*/, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        count_element();
        if (frames_.size() >= kMaxSceneNesting) {
          fail(ErrorCode::kInvalidInput, what_, path(frames_.size()),
               "objects and arrays nest deeper than {} levels", kMaxSceneNesting);
        }
        frames_.push_back(Frame{event == json::parse_event_t::array_start, 0, {}, {}});
        break;
      case json::parse_event_t::key: {
        Frame& frame = frames_.back();
        std::string key = parsed.get<std::string>();
        if (!frame.keys.insert(key).second) {
          fail(ErrorCode::kInvalidInput, what_, path(frames_.size() - 1),
               "key '{}' appears twice in one object", scene_detail::shown(key));
        }
        frame.key = std::move(key);
        break;
      }
      case json::parse_event_t::value: count_element(); break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end: frames_.pop_back(); break;
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
  std::vector<Frame> frames_;
};

std::string_view without_exception_id(std::string_view message) {
  // "[json.exception.parse_error.101] parse error at ..." -> "parse error at ..."
  const auto end = message.find("] ");
  return message.starts_with("[json.exception.") && end != std::string_view::npos
             ? message.substr(end + 2)
             : message;
}

json parse_json(std::string_view text, std::string_view what) {
  SyntaxGuard guard(what);
  try {
    return json::parse(text.begin(), text.end(),
                       [&guard](int depth, json::parse_event_t event, json& parsed) {
                         return guard(depth, event, parsed);
                       });
  } catch (const json::out_of_range& e) {  // 406: a number overflows binary64
    fail(ErrorCode::kInvalidInput, what, guard.current_value_path(),
         "is not a finite number: {}", without_exception_id(e.what()));
  } catch (const json::exception& e) {
    fail(ErrorCode::kInvalidInput, what, "", "not valid JSON: {}", without_exception_id(e.what()));
  }
}

// Typed access with errors naming the path.
class Reader {
 public:
  explicit Reader(std::string_view what) : what_(what) {}

  [[noreturn]] void wrong_type(const json& v, std::string_view path,
                               std::string_view expected) const {
    fail(ErrorCode::kInvalidInput, what_, path, "expected {}, got {}", expected, describe(v));
  }

  void object(const json& v, std::string_view path) const {
    if (!v.is_object()) wrong_type(v, path, "an object");
  }

  void array(const json& v, std::string_view path) const {
    if (!v.is_array()) wrong_type(v, path, "an array");
  }

  // Rejects keys not in `allowed`, with a distinct message for reserved ones.
  void keys(const json& obj, std::string_view path, Keys allowed, Keys reserved) const {
    for (const auto& [key, value] : obj.items()) {
      if (contains(allowed, key)) continue;
      if (contains(reserved, key)) {
        fail(ErrorCode::kInvalidInput, what_, key_path(path, key),
             "key '{}' is reserved for a later version of the scene format (this reader reads "
             "version {})",
             key, kSceneFormatVersion);
      }
      fail(ErrorCode::kInvalidInput, what_, key_path(path, key),
           "unknown key '{}' (allowed {}: {})", scene_detail::shown(key), path.empty() ? "at the top level" : "here",
           join(allowed));
    }
  }

  const json* find(const json& obj, std::string_view key) const {
    const auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
  }

  const json& require(const json& obj, std::string_view path, std::string_view key) const {
    if (const json* v = find(obj, key)) return *v;
    fail(ErrorCode::kInvalidInput, what_, path, "missing required key '{}'", key);
  }

  std::uint64_t integer(const json& v, std::string_view path, std::uint64_t lo,
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

  double number(const json& v, std::string_view path) const {
    if (!v.is_number()) wrong_type(v, path, "a number");
    const double value = v.get<double>();
    if (!std::isfinite(value)) {
      fail(ErrorCode::kInvalidInput, what_, path, "must be a finite number, got {}", value);
    }
    return value;
  }

  std::string string(const json& v, std::string_view path) const {
    if (!v.is_string()) wrong_type(v, path, "a string");
    return v.get<std::string>();
  }

  std::string_view what() const { return what_; }

 private:
  std::string_view what_;
};

Limit read_limit(const Reader& r, const json& v, const std::string& path) {
  r.object(v, path);
  r.keys(v, path, kLimitKeys, {});
  Limit limit;
  limit.var = r.string(r.require(v, path, "var"), key_path(path, "var"));
  if (const json* min = r.find(v, "min")) limit.min = r.number(*min, key_path(path, "min"));
  if (const json* max = r.find(v, "max")) limit.max = r.number(*max, key_path(path, "max"));
  return limit;
}

SubVolume read_subvolume(const Reader& r, const json& v, const std::string& path) {
  r.object(v, path);
  r.keys(v, path, kSubVolumeKeys, kReservedSubVolumeKeys);
  SubVolume sv;
  sv.id = static_cast<std::uint32_t>(
      r.integer(r.require(v, path, "id"), key_path(path, "id"), 1, kMaxSubVolumeId));
  if (const json* name = r.find(v, "name")) sv.name = r.string(*name, key_path(path, "name"));
  if (const json* limits = r.find(v, "limits")) {
    const std::string limits_path = key_path(path, "limits");
    r.array(*limits, limits_path);
    for (std::size_t i = 0; i < limits->size(); ++i) {
      sv.limits.push_back(read_limit(r, (*limits)[i], index_path(limits_path, i)));
    }
  }
  if (const json* domain = r.find(v, "domain")) {
    const std::string domain_path = key_path(path, "domain");
    r.object(*domain, domain_path);
    for (const auto& [axis, range] : domain->items()) {
      const std::string p = key_path(domain_path, axis);
      if (!range.is_array() || range.size() != 2) {
        r.wrong_type(range, p, "an array of two numbers [lo, hi]");
      }
      sv.domain[axis] = AxisRange{r.number(range[0], index_path(p, 0)),
                                  r.number(range[1], index_path(p, 1))};
    }
  }
  return sv;
}

Scene read_scene(const Reader& r, const json& root) {
  if (!root.is_object()) r.wrong_type(root, "", "a JSON object at the top level");
  // The version first: an older reader must say "newer" rather than "unknown key".
  if (const json* v = r.find(root, "format_version")) {
    const std::uint64_t version =
        r.integer(*v, "format_version", 1, std::numeric_limits<std::uint64_t>::max());
    if (version > kSceneFormatVersion) {
      throw make_error(ErrorCode::kVersionTooNew,
                       "{}: format_version {} is newer than this reader (max {})", r.what(),
                       version, kSceneFormatVersion);
    }
  }
  r.keys(root, "", kSceneKeys, kReservedSceneKeys);
  Scene scene;
  if (const json* t = r.find(root, "time")) {
    scene.time = static_cast<std::uint32_t>(
        r.integer(*t, "time", 0, std::numeric_limits<std::uint32_t>::max()));
  }
  const json& subvolumes = r.require(root, "", "subvolumes");
  r.array(subvolumes, "subvolumes");
  for (std::size_t i = 0; i < subvolumes.size(); ++i) {
    scene.subvolumes.push_back(read_subvolume(r, subvolumes[i], index_path("subvolumes", i)));
  }
  if (const json* attributes = r.find(root, "attributes")) {
    r.array(*attributes, "attributes");
    for (std::size_t i = 0; i < attributes->size(); ++i) {
      scene.attributes.push_back(r.string((*attributes)[i], index_path("attributes", i)));
    }
  }
  return scene;
}

}  // namespace

Scene parse_scene(std::string_view json_text, std::string_view what) {
  if (json_text.size() > kMaxSceneBytes) {
    fail(ErrorCode::kInvalidInput, what, "", "the scene has {} bytes, more than the limit of {}",
         json_text.size(), kMaxSceneBytes);
  }
  const json root = parse_json(json_text, what);
  Scene scene;
  try {
    scene = read_scene(Reader(what), root);
  } catch (const json::exception& e) {  // every access is type-checked first: a bug
    fail(ErrorCode::kInternal, what, "", "unexpected JSON error: {}", e.what());
  }
  validate_scene(scene, what);
  return scene;
}

Scene load_scene_file(const std::filesystem::path& path) {
  const ReadOnlyFile file(path);  // kNotFound / kIo naming the path
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    fail(ErrorCode::kIo, path.string(), "", "cannot read: is a directory, not a scene file");
  }
  if (file.size() > kMaxSceneBytes) {
    fail(ErrorCode::kInvalidInput, path.string(), "",
         "the scene has {} bytes, more than the limit of {}", file.size(), kMaxSceneBytes);
  }
  std::string text(file.size(), '\0');
  file.read_at(0, std::as_writable_bytes(std::span(text)));
  return parse_scene(text, path.string());
}

std::string scene_to_json(const Scene& scene) {
  validate_scene(scene, "scene");
  using nlohmann::ordered_json;
  ordered_json out;
  out["format_version"] = kSceneFormatVersion;
  out["time"] = scene.time;
  ordered_json subvolumes = ordered_json::array();
  for (const SubVolume& sv : scene.subvolumes) {
    ordered_json o;
    o["id"] = sv.id;
    o["name"] = sv.name;
    ordered_json limits = ordered_json::array();
    for (const Limit& l : sv.limits) {
      ordered_json lj;
      lj["var"] = l.var;
      if (l.min) lj["min"] = *l.min;
      if (l.max) lj["max"] = *l.max;
      limits.push_back(std::move(lj));
    }
    o["limits"] = std::move(limits);
    if (!sv.domain.empty()) {
      ordered_json domain = ordered_json::object();
      for (const auto& [axis, range] : sv.domain) {  // std::map: sorted by byte value
        domain[axis] = ordered_json::array({range.lo, range.hi});
      }
      o["domain"] = std::move(domain);
    }
    subvolumes.push_back(std::move(o));
  }
  out["subvolumes"] = std::move(subvolumes);
  out["attributes"] = scene.attributes;
  try {
    return out.dump();
  } catch (const ordered_json::exception& e) {  // validate_scene checked UTF-8: a bug
    throw make_error(ErrorCode::kInternal, "scene: cannot write JSON: {}", e.what());
  }
}

}  // namespace strielad
