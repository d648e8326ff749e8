// SPDX-License-Identifier: Apache-2.0
// Camera-path JSON (formats/camera-path.md): parsing with key, type and syntax checks
// (repeated keys, nesting) naming the offending path; the canonical writer; files.
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/file_io.h"
#include "lod/camera_path.h"
#include "lod/camera_path_errors.h"

namespace strielad::lod {
namespace {

using nlohmann::json;
using path_detail::fail;
using path_detail::index_path;
using path_detail::key_path;

using Keys = std::span<const std::string_view>;
constexpr std::array<std::string_view, 3> kTopKeys = {"format_version", "name", "keyframes"};
constexpr std::array<std::string_view, 1> kReservedTopKeys = {"interpolation"};
constexpr std::array<std::string_view, 4> kKeyframeKeys = {"t", "eye", "target", "fov_deg"};
constexpr std::array<std::string_view, 2> kReservedKeyframeKeys = {"up", "step"};

bool listed(Keys keys, std::string_view key) {
  for (std::string_view k : keys) {
    if (k == key) return true;
  }
  return false;
}

std::string join(Keys keys) {
  std::string out;
  for (std::string_view k : keys) out += out.empty() ? std::string(k) : fmt::format(", {}", k);
  return out;
}

std::string describe(const json& v) {
  switch (v.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return v.get<bool>() ? "true" : "false";
    case json::value_t::number_integer:
    case json::value_t::number_unsigned:
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

// Parser callback: rejects a repeated key in one object and nesting deeper than
// kMaxCameraPathNesting while parsing, knowing the path of the value being parsed.
class SyntaxGuard {
 public:
  explicit SyntaxGuard(std::string_view what) : what_(what) {}

  bool operator()(int /*depth*/, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        count_element();
        if (frames_.size() >= kMaxCameraPathNesting) {
          fail(ErrorCode::kInvalidInput, what_, path(frames_.size()),
               "objects and arrays nest deeper than {} levels", kMaxCameraPathNesting);
        }
        frames_.push_back(Frame{event == json::parse_event_t::array_start, 0, {}, {}});
        break;
      case json::parse_event_t::key: {
        Frame& frame = frames_.back();
        std::string key = parsed.get<std::string>();
        if (!frame.keys.insert(key).second) {
          fail(ErrorCode::kInvalidInput, what_, path(frames_.size() - 1),
               "key '{}' appears twice in one object", path_detail::shown(key));
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

  // Path of the value being read now (for errors raised before its event).
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

class Reader {
 public:
  explicit Reader(std::string_view what) : what_(what) {}

  [[noreturn]] void wrong_type(const json& v, std::string_view path,
                               std::string_view expected) const {
    fail(ErrorCode::kInvalidInput, what_, path, "expected {}, got {}", expected, describe(v));
  }

  void keys(const json& obj, std::string_view path, Keys allowed, Keys reserved) const {
    for (const auto& [key, value] : obj.items()) {
      if (listed(allowed, key)) continue;
      if (listed(reserved, key)) {
        fail(ErrorCode::kInvalidInput, what_, key_path(path, key),
             "key '{}' is reserved for a later version of the camera-path format (this reader "
             "reads version {})",
             key, kCameraPathFormatVersion);
      }
      fail(ErrorCode::kInvalidInput, what_, key_path(path, key), "unknown key '{}' (allowed {}: {})",
           path_detail::shown(key), path.empty() ? "at the top level" : "here", join(allowed));
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

  double number(const json& v, std::string_view path) const {
    if (!v.is_number()) wrong_type(v, path, "a number");
    const double value = v.get<double>();
    if (!std::isfinite(value)) {
      fail(ErrorCode::kInvalidInput, what_, path, "must be a finite number, got {}", value);
    }
    return value;
  }

  Vec3 point(const json& v, const std::string& path) const {
    if (!v.is_array() || v.size() != 3) wrong_type(v, path, "an array of three numbers [x, y, z]");
    return {number(v[0], index_path(path, 0)), number(v[1], index_path(path, 1)),
            number(v[2], index_path(path, 2))};
  }

  std::string_view what() const { return what_; }

 private:
  std::string_view what_;
};

Keyframe read_keyframe(const Reader& r, const json& v, const std::string& path) {
  if (!v.is_object()) r.wrong_type(v, path, "an object");
  r.keys(v, path, kKeyframeKeys, kReservedKeyframeKeys);
  Keyframe k;
  k.t = r.number(r.require(v, path, "t"), key_path(path, "t"));
  k.eye = r.point(r.require(v, path, "eye"), key_path(path, "eye"));
  k.target = r.point(r.require(v, path, "target"), key_path(path, "target"));
  if (const json* fov = r.find(v, "fov_deg")) k.fov_deg = r.number(*fov, key_path(path, "fov_deg"));
  return k;
}

CameraPath read_path(const Reader& r, const json& root) {
  if (!root.is_object()) r.wrong_type(root, "", "a JSON object at the top level");
  if (const json* v = r.find(root, "format_version")) {
    if (!v->is_number_integer()) r.wrong_type(*v, "format_version", "an integer");
    if (!v->is_number_unsigned() || v->get<std::uint64_t>() < 1) {
      fail(ErrorCode::kInvalidInput, r.what(), "format_version", "must be an integer >= 1, got {}",
           v->dump());
    }
    const auto version = v->get<std::uint64_t>();
    if (version > kCameraPathFormatVersion) {
      throw make_error(ErrorCode::kVersionTooNew,
                       "{}: format_version {} is newer than this reader (max {})", r.what(),
                       version, kCameraPathFormatVersion);
    }
  }
  r.keys(root, "", kTopKeys, kReservedTopKeys);
  CameraPath path;
  if (const json* name = r.find(root, "name")) {
    if (!name->is_string()) r.wrong_type(*name, "name", "a string");
    path.name = name->get<std::string>();
  }
  const json& keyframes = r.require(root, "", "keyframes");
  if (!keyframes.is_array()) r.wrong_type(keyframes, "keyframes", "an array");
  if (keyframes.size() > kMaxKeyframes) {
    fail(ErrorCode::kInvalidInput, r.what(), "keyframes", "has {} keyframes, more than {}",
         keyframes.size(), kMaxKeyframes);
  }
  for (std::size_t i = 0; i < keyframes.size(); ++i) {
    path.keyframes.push_back(read_keyframe(r, keyframes[i], index_path("keyframes", i)));
  }
  return path;
}

}  // namespace

CameraPath parse_camera_path(std::string_view json_text, std::string_view what) {
  if (json_text.size() > kMaxCameraPathBytes) {
    fail(ErrorCode::kInvalidInput, what, "", "the camera path has {} bytes, more than the limit of {}",
         json_text.size(), kMaxCameraPathBytes);
  }
  const json root = parse_json(json_text, what);
  CameraPath path;
  try {
    path = read_path(Reader(what), root);
  } catch (const json::exception& e) {  // every access is type-checked first: a bug
    fail(ErrorCode::kInternal, what, "", "unexpected JSON error: {}", e.what());
  }
  validate_camera_path(path, what);
  return path;
}

CameraPath load_camera_path_file(const std::filesystem::path& path) {
  const ReadOnlyFile file(path);  // kNotFound / kIo naming the path
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    fail(ErrorCode::kIo, path.string(), "", "cannot read: is a directory, not a camera path");
  }
  if (file.size() > kMaxCameraPathBytes) {
    fail(ErrorCode::kInvalidInput, path.string(), "",
         "the camera path has {} bytes, more than the limit of {}", file.size(),
         kMaxCameraPathBytes);
  }
  std::string text(file.size(), '\0');
  file.read_at(0, std::as_writable_bytes(std::span(text)));
  return parse_camera_path(text, path.string());
}

std::string camera_path_to_json(const CameraPath& path) {
  validate_camera_path(path, "camera path");
  using nlohmann::ordered_json;
  ordered_json out;
  out["format_version"] = kCameraPathFormatVersion;
  out["name"] = path.name;
  ordered_json keyframes = ordered_json::array();
  for (const Keyframe& k : path.keyframes) {
    ordered_json o;
    o["t"] = k.t;
    o["eye"] = ordered_json::array({k.eye[0], k.eye[1], k.eye[2]});
    o["target"] = ordered_json::array({k.target[0], k.target[1], k.target[2]});
    o["fov_deg"] = k.fov_deg;
    keyframes.push_back(std::move(o));
  }
  out["keyframes"] = std::move(keyframes);
  return out.dump();
}

}  // namespace strielad::lod
