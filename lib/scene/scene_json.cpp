// SPDX-License-Identifier: Apache-2.0
// Scene JSON: parsing with key, type and syntax checks (duplicate keys, nesting) that
// name the offending path; the canonical writer; reading a scene file.
#include <array>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/strict_json.h"
#include "scene/scene.h"

namespace strielad {
namespace {

using strict_json::index_path;
using strict_json::Json;
using strict_json::key_path;
using strict_json::Reader;

constexpr std::array<std::string_view, 8> kSceneKeys = {
    "format_version", "time", "subvolumes", "attributes",
    "slices", "terrain", "sun", "trajectories"};  // the last four: version 2
// The keys added by version 2 (formats/scene.md, "Version history").
constexpr std::array<std::string_view, 4> kVersion2SceneKeys = {"slices", "terrain", "sun",
                                                                "trajectories"};
// Reserved for later versions (formats/scene.md, "Extending the format").
constexpr std::array<std::string_view, 2> kReservedSceneKeys = {"advection", "camera"};
constexpr std::array<std::string_view, 8> kSliceKeys = {"id",  "name", "axis",     "value",
                                                        "level", "var", "colormap", "range"};
constexpr std::array<std::string_view, 2> kLevelKeys = {"var", "value"};
constexpr std::array<std::string_view, 3> kTerrainKeys = {"dem", "var", "image"};
constexpr std::array<std::string_view, 3> kSunKeys = {"mode", "elevation", "azimuth"};
constexpr std::array<std::string_view, 2> kTrajectoriesKeys = {"file", "minutes"};
constexpr std::array<std::string_view, 5> kSubVolumeKeys = {"id", "name", "limits", "domain",
                                                            "geographic"};  // the last: version 3
constexpr std::array<std::string_view, 3> kGeographicKeys = {"lon", "lat",
                                                             "height"};  // the last: version 4
constexpr std::array<std::string_view, 1> kReservedSubVolumeKeys = {"style"};
constexpr std::array<std::string_view, 3> kLimitKeys = {"var", "min", "max"};

constexpr strict_json::Format kSceneJson{.name = "scene",
                                         .noun = "scene",
                                         .file_noun = "a scene file",
                                         .version = kSceneFormatVersion,
                                         .max_bytes = kMaxSceneBytes,
                                         .max_nesting = kMaxSceneNesting,
                                         .integers_apart = true};

Limit read_limit(const Reader& r, const Json& v, const std::string& path) {
  r.object(v, path);
  r.keys(v, path, kLimitKeys, {});
  Limit limit;
  limit.var = r.string(r.require(v, path, "var"), key_path(path, "var"));
  if (const Json* min = r.find(v, "min")) limit.min = r.number(*min, key_path(path, "min"));
  if (const Json* max = r.find(v, "max")) limit.max = r.number(*max, key_path(path, "max"));
  return limit;
}

AxisRange read_range(const Reader& r, const Json& range, const std::string& p) {
  if (!range.is_array() || range.size() != 2) {
    r.wrong_type(range, p, "an array of two numbers [lo, hi]");
  }
  return AxisRange{r.number(range[0], index_path(p, 0)), r.number(range[1], index_path(p, 1))};
}

SubVolume read_subvolume(const Reader& r, const Json& v, const std::string& path,
                         std::uint64_t declared) {
  r.object(v, path);
  r.keys(v, path, kSubVolumeKeys, kReservedSubVolumeKeys);
  SubVolume sv;
  sv.id = static_cast<std::uint32_t>(
      r.integer(r.require(v, path, "id"), key_path(path, "id"), 1, kMaxSubVolumeId));
  if (const Json* name = r.find(v, "name")) sv.name = r.string(*name, key_path(path, "name"));
  if (const Json* limits = r.find(v, "limits")) {
    const std::string limits_path = key_path(path, "limits");
    r.array(*limits, limits_path);
    for (std::size_t i = 0; i < limits->size(); ++i) {
      sv.limits.push_back(read_limit(r, (*limits)[i], index_path(limits_path, i)));
    }
  }
  if (const Json* domain = r.find(v, "domain")) {
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
  if (const Json* geographic = r.find(v, "geographic")) {
    const std::string p = key_path(path, "geographic");
    if (declared < kSceneVersionGeographicBox) {
      strict_json::fail(ErrorCode::kInvalidInput, r.what(), p,
                        "was added in format_version {}; the scene declares {} (write "
                        "\"format_version\": {})",
                        kSceneVersionGeographicBox, declared, kSceneVersionGeographicBox);
    }
    r.object(*geographic, p);
    r.keys(*geographic, p, kGeographicKeys, {});
    GeographicBox box;
    if (const Json* lon = r.find(*geographic, "lon")) box.lon = read_range(r, *lon, key_path(p, "lon"));
    if (const Json* lat = r.find(*geographic, "lat")) box.lat = read_range(r, *lat, key_path(p, "lat"));
    if (const Json* height = r.find(*geographic, "height")) {
      if (declared < kSceneVersionGeographicHeight) {
        strict_json::fail(ErrorCode::kInvalidInput, r.what(), key_path(p, "height"),
                          "was added in format_version {}; the scene declares {} (write "
                          "\"format_version\": {})",
                          kSceneVersionGeographicHeight, declared, kSceneVersionGeographicHeight);
      }
      box.height = read_range(r, *height, key_path(p, "height"));
    }
    sv.geographic = box;
  }
  return sv;
}

Slice read_slice(const Reader& r, const Json& v, const std::string& path) {
  r.object(v, path);
  r.keys(v, path, kSliceKeys, {});
  Slice slice;
  slice.id = static_cast<std::uint32_t>(
      r.integer(r.require(v, path, "id"), key_path(path, "id"), 1, kMaxSliceId));
  if (const Json* name = r.find(v, "name")) slice.name = r.string(*name, key_path(path, "name"));
  const Json* axis = r.find(v, "axis");
  const Json* level = r.find(v, "level");
  const Json* value = r.find(v, "value");
  if ((axis == nullptr) == (level == nullptr)) {
    strict_json::fail(ErrorCode::kInvalidInput, r.what(), path,
                      "a slice needs exactly one of 'axis' (a plane) and 'level' (an iso-level)");
  }
  if (axis != nullptr) {
    slice.axis = r.string(*axis, key_path(path, "axis"));
    if (slice.axis.empty()) {
      strict_json::fail(ErrorCode::kInvalidInput, r.what(), key_path(path, "axis"),
                        "must name an axis, got \"\"");
    }
    if (value == nullptr) {
      strict_json::fail(ErrorCode::kInvalidInput, r.what(), path,
                        "an axis slice needs 'value', the plane's coordinate");
    }
    slice.value = r.number(*value, key_path(path, "value"));
  } else {
    const std::string level_path = key_path(path, "level");
    if (value != nullptr) {
      strict_json::fail(ErrorCode::kInvalidInput, r.what(), key_path(path, "value"),
                        "a level slice gives its value inside 'level': {{\"var\": ..., \"value\": ...}}");
    }
    r.object(*level, level_path);
    r.keys(*level, level_path, kLevelKeys, {});
    slice.level_var = r.string(r.require(*level, level_path, "var"), key_path(level_path, "var"));
    if (slice.level_var.empty()) {
      strict_json::fail(ErrorCode::kInvalidInput, r.what(), key_path(level_path, "var"),
                        "must name a variable, got \"\"");
    }
    slice.value = r.number(r.require(*level, level_path, "value"), key_path(level_path, "value"));
  }
  slice.var = r.string(r.require(v, path, "var"), key_path(path, "var"));
  if (const Json* colormap = r.find(v, "colormap")) {
    slice.colormap = r.string(*colormap, key_path(path, "colormap"));
  }
  if (const Json* range = r.find(v, "range")) {
    const std::string p = key_path(path, "range");
    if (!range->is_array() || range->size() != 2) {
      r.wrong_type(*range, p, "an array of two numbers [lo, hi]");
    }
    slice.range = AxisRange{r.number((*range)[0], index_path(p, 0)),
                            r.number((*range)[1], index_path(p, 1))};
  }
  return slice;
}

Terrain read_terrain(const Reader& r, const Json& v) {
  r.object(v, "terrain");
  r.keys(v, "terrain", kTerrainKeys, {});
  Terrain t;
  t.dem = r.string(r.require(v, "terrain", "dem"), "terrain.dem");
  const auto non_empty = [&](const Json& value, std::string_view path, std::string_view of) {
    std::string text = r.string(value, path);
    if (text.empty()) {
      strict_json::fail(ErrorCode::kInvalidInput, r.what(), path, "must name {}, got \"\"", of);
    }
    return text;
  };
  if (const Json* var = r.find(v, "var")) t.var = non_empty(*var, "terrain.var", "a variable");
  if (const Json* image = r.find(v, "image")) t.image = non_empty(*image, "terrain.image", "a file");
  return t;
}

Sun read_sun(const Reader& r, const Json& v) {
  r.object(v, "sun");
  r.keys(v, "sun", kSunKeys, {});
  Sun sun;
  const Json* mode = r.find(v, "mode");
  const Json* elevation = r.find(v, "elevation");
  const Json* azimuth = r.find(v, "azimuth");
  if (mode != nullptr) {
    if (elevation != nullptr || azimuth != nullptr) {
      strict_json::fail(ErrorCode::kInvalidInput, r.what(), "sun",
                        "give either 'mode' or 'elevation' and 'azimuth', not both");
    }
    const std::string m = r.string(*mode, "sun.mode");
    if (m != "time") {
      strict_json::fail(ErrorCode::kInvalidInput, r.what(), "sun.mode",
                        "must be \"time\" (the true sun at the simulation time), got \"{}\"",
                        strict_json::shown(m));
    }
    return sun;
  }
  if (elevation == nullptr || azimuth == nullptr) {
    strict_json::fail(ErrorCode::kInvalidInput, r.what(), "sun",
                      "needs {{\"mode\": \"time\"}} or both 'elevation' and 'azimuth'");
  }
  sun.from_time = false;
  sun.elevation_deg = r.number(*elevation, "sun.elevation");
  sun.azimuth_deg = r.number(*azimuth, "sun.azimuth");
  return sun;
}

Trajectories read_trajectories(const Reader& r, const Json& v) {
  r.object(v, "trajectories");
  r.keys(v, "trajectories", kTrajectoriesKeys, {});
  Trajectories t;
  t.file = r.string(r.require(v, "trajectories", "file"), "trajectories.file");
  if (const Json* minutes = r.find(v, "minutes")) {
    t.minutes = r.number(*minutes, "trajectories.minutes");
  }
  return t;
}

Scene read_scene(const Reader& r, const Json& root) {
  if (!root.is_object()) r.wrong_type(root, "", "a JSON object at the top level");
  r.format_version(root);  // first: an older reader must say "newer", not "unknown key"
  r.keys(root, "", kSceneKeys, kReservedSceneKeys);
  // A key newer than the scene's declared version is rejected (formats/scene.md,
  // "Extending the format", rule 3).
  std::uint64_t declared = 1;
  if (const Json* v = r.find(root, "format_version")) declared = v->get<std::uint64_t>();
  for (std::string_view key : kVersion2SceneKeys) {
    if (declared < kSceneVersionGeography && r.find(root, key) != nullptr) {
      strict_json::fail(ErrorCode::kInvalidInput, r.what(), key,
                        "was added in format_version {}; the scene declares {} (write "
                        "\"format_version\": {})",
                        kSceneVersionGeography, declared, kSceneVersionGeography);
    }
  }
  Scene scene;
  if (const Json* t = r.find(root, "time")) {
    scene.time = static_cast<std::uint32_t>(
        r.integer(*t, "time", 0, std::numeric_limits<std::uint32_t>::max()));
  }
  const Json& subvolumes = r.require(root, "", "subvolumes");
  r.array(subvolumes, "subvolumes");
  for (std::size_t i = 0; i < subvolumes.size(); ++i) {
    scene.subvolumes.push_back(
        read_subvolume(r, subvolumes[i], index_path("subvolumes", i), declared));
  }
  if (const Json* attributes = r.find(root, "attributes")) {
    r.array(*attributes, "attributes");
    for (std::size_t i = 0; i < attributes->size(); ++i) {
      scene.attributes.push_back(r.string((*attributes)[i], index_path("attributes", i)));
    }
  }
  if (const Json* slices = r.find(root, "slices")) {
    r.array(*slices, "slices");
    if (slices->size() > kMaxSlices) {
      strict_json::fail(ErrorCode::kInvalidInput, r.what(), "slices",
                        "has {} slices, more than the limit of {}", slices->size(), kMaxSlices);
    }
    for (std::size_t i = 0; i < slices->size(); ++i) {
      scene.slices.push_back(read_slice(r, (*slices)[i], index_path("slices", i)));
    }
  }
  if (const Json* terrain = r.find(root, "terrain")) scene.terrain = read_terrain(r, *terrain);
  if (const Json* sun = r.find(root, "sun")) scene.sun = read_sun(r, *sun);
  if (const Json* t = r.find(root, "trajectories")) scene.trajectories = read_trajectories(r, *t);
  return scene;
}

}  // namespace

Scene parse_scene(std::string_view json_text, std::string_view what) {
  Scene scene = strict_json::read_document(json_text, what, kSceneJson, read_scene);
  validate_scene(scene, what);
  return scene;
}

Scene load_scene_file(const std::filesystem::path& path) {
  return parse_scene(strict_json::read_file(path, kSceneJson), path.string());
}

std::string scene_to_json(const Scene& scene) {
  validate_scene(scene, "scene");
  using nlohmann::ordered_json;
  ordered_json out;
  out["format_version"] = scene.required_format_version();
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
    if (sv.geographic) {
      ordered_json geographic = ordered_json::object();
      if (sv.geographic->lon) geographic["lon"] = ordered_json::array({sv.geographic->lon->lo, sv.geographic->lon->hi});
      if (sv.geographic->lat) geographic["lat"] = ordered_json::array({sv.geographic->lat->lo, sv.geographic->lat->hi});
      if (sv.geographic->height) {
        geographic["height"] = ordered_json::array({sv.geographic->height->lo, sv.geographic->height->hi});
      }
      o["geographic"] = std::move(geographic);
    }
    subvolumes.push_back(std::move(o));
  }
  out["subvolumes"] = std::move(subvolumes);
  out["attributes"] = scene.attributes;
  if (!scene.slices.empty()) {
    ordered_json slices = ordered_json::array();
    for (const Slice& slice : scene.slices) {
      ordered_json o;
      o["id"] = slice.id;
      o["name"] = slice.name;
      if (slice.is_level()) {
        ordered_json level;
        level["var"] = slice.level_var;
        level["value"] = slice.value;
        o["level"] = std::move(level);
      } else {
        o["axis"] = slice.axis;
        o["value"] = slice.value;
      }
      o["var"] = slice.var;
      o["colormap"] = slice.colormap;
      if (slice.range) o["range"] = ordered_json::array({slice.range->lo, slice.range->hi});
      slices.push_back(std::move(o));
    }
    out["slices"] = std::move(slices);
  }
  if (scene.terrain) {
    ordered_json t;
    t["dem"] = scene.terrain->dem;
    if (!scene.terrain->var.empty()) t["var"] = scene.terrain->var;
    if (!scene.terrain->image.empty()) t["image"] = scene.terrain->image;
    out["terrain"] = std::move(t);
  }
  if (scene.sun) {
    ordered_json sun;
    if (scene.sun->from_time) {
      sun["mode"] = "time";
    } else {
      sun["elevation"] = scene.sun->elevation_deg;
      sun["azimuth"] = scene.sun->azimuth_deg;
    }
    out["sun"] = std::move(sun);
  }
  if (scene.trajectories) {
    ordered_json t;
    t["file"] = scene.trajectories->file;
    t["minutes"] = scene.trajectories->minutes;
    out["trajectories"] = std::move(t);
  }
  try {
    return out.dump();
  } catch (const ordered_json::exception& e) {  // validate_scene checked UTF-8: a bug
    throw make_error(ErrorCode::kInternal, "scene: cannot write JSON: {}", e.what());
  }
}

}  // namespace strielad
