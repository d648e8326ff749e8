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

constexpr std::array<std::string_view, 4> kSceneKeys = {"format_version", "time", "subvolumes",
                                                        "attributes"};
// Reserved for later versions (formats/scene.md, "Extending the format").
constexpr std::array<std::string_view, 6> kReservedSceneKeys = {
    "slices", "trajectories", "terrain", "sun", "advection", "camera"};
constexpr std::array<std::string_view, 4> kSubVolumeKeys = {"id", "name", "limits", "domain"};
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

SubVolume read_subvolume(const Reader& r, const Json& v, const std::string& path) {
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
  return sv;
}

Scene read_scene(const Reader& r, const Json& root) {
  if (!root.is_object()) r.wrong_type(root, "", "a JSON object at the top level");
  r.format_version(root);  // first: an older reader must say "newer", not "unknown key"
  r.keys(root, "", kSceneKeys, kReservedSceneKeys);
  Scene scene;
  if (const Json* t = r.find(root, "time")) {
    scene.time = static_cast<std::uint32_t>(
        r.integer(*t, "time", 0, std::numeric_limits<std::uint32_t>::max()));
  }
  const Json& subvolumes = r.require(root, "", "subvolumes");
  r.array(subvolumes, "subvolumes");
  for (std::size_t i = 0; i < subvolumes.size(); ++i) {
    scene.subvolumes.push_back(read_subvolume(r, subvolumes[i], index_path("subvolumes", i)));
  }
  if (const Json* attributes = r.find(root, "attributes")) {
    r.array(*attributes, "attributes");
    for (std::size_t i = 0; i < attributes->size(); ++i) {
      scene.attributes.push_back(r.string((*attributes)[i], index_path("attributes", i)));
    }
  }
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
