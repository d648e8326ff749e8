// SPDX-License-Identifier: Apache-2.0
#include "format/manifest.h"

#include <cmath>
#include <cstring>

#include "core/byte_io.h"
#include "core/checksum.h"
#include "core/error.h"
#include "format/json_fields.h"
#include "format/step_file_format.h"
#include "octree/octree_layout.h"

namespace strielad::format {
namespace {

using nlohmann::json;
constexpr std::string_view kManifestMagic = "STRLDMAN";
constexpr std::size_t kFrameHeader = 24, kFrameTrailer = 8;

using json_fields::get;
using json_fields::hex64;
using json_fields::parse_hex64;

std::optional<double> get_optional(const json& j, std::string_view key, std::string_view what) {
  if (!j.contains(std::string(key))) return std::nullopt;
  return get<double>(j, key, what);
}

json axis_json(const Axis& a) {
  json j{{"name", a.name},         {"kind", std::string(axis_kind_name(a.kind))},
         {"units", a.units},       {"standard_name", a.standard_name},
         {"long_name", a.long_name}, {"positive", a.positive},
         {"values", a.values}};
  if (a.periodic) j["periodic"] = true;  // version 4
  return j;
}

bool is_projection_kind(AxisKind kind) {
  return kind == AxisKind::kProjectionX || kind == AxisKind::kProjectionY;
}

Axis axis_from_json(const json& j, std::string_view what, std::uint32_t version) {
  Axis a;
  a.name = get<std::string>(j, "name", what);
  a.kind = axis_kind_from_name(get<std::string>(j, "kind", what));
  if (is_projection_kind(a.kind) && version < kManifestVersionGeoreference) {
    throw make_error(ErrorCode::kCorrupt, "{}: axis kind '{}' needs format version {} (this is {})",
                     what, axis_kind_name(a.kind), kManifestVersionGeoreference, version);
  }
  if (a.kind == AxisKind::kIndex && version < kManifestVersionGeometry) {
    throw make_error(ErrorCode::kCorrupt, "{}: axis kind 'index' needs format version {} (this is {})",
                     what, kManifestVersionGeometry, version);
  }
  if (const auto it = j.find("periodic"); it != j.end()) {
    if (version < kManifestVersionGeoreference) {
      throw make_error(ErrorCode::kCorrupt, "{}: key 'periodic' needs format version {} (this is {})",
                       what, kManifestVersionGeoreference, version);
    }
    a.periodic = get<bool>(j, "periodic", what);
  }
  a.units = get<std::string>(j, "units", what);
  a.standard_name = get<std::string>(j, "standard_name", what);
  a.long_name = get<std::string>(j, "long_name", what);
  a.positive = get<std::string>(j, "positive", what);
  a.values = get<std::vector<double>>(j, "values", what);
  try {
    check_axis_values(a, what);
  } catch (const Error& e) {
    throw Error(ErrorCode::kCorrupt, e.what());
  }
  return a;
}

void check_version(std::uint32_t version, std::string_view what) {
  if (version > kManifestFormatVersion) {
    throw make_error(ErrorCode::kVersionTooNew,
                     "{}: format version {} is newer than this reader (max {})", what, version,
                     kManifestFormatVersion);
  }
  if (version == 0) throw make_error(ErrorCode::kCorrupt, "{}: format version 0 is invalid", what);
}

json levels_json(const OctreeLayout& layout) {
  json levels = json::array();
  for (std::size_t l = 0; l < layout.level_count(); ++l) {
    const LevelShape& s = layout.level(l);
    levels.push_back(json{{"samples", s.samples},
                          {"stride", s.stride},
                          {"nodes", s.nodes},
                          {"first_node", s.first_node}});
  }
  return levels;
}

}  // namespace

std::size_t Manifest::variable_index(std::string_view name) const {
  std::string names;
  for (std::size_t i = 0; i < variables.size(); ++i) {
    if (variables[i].name == name) return i;
    names += (i ? ", " : "") + variables[i].name;
  }
  throw make_error(ErrorCode::kNotFound, "variable '{}' is not in the store (it has: {})", name,
                   names);
}

std::uint32_t version_for_codecs(const Manifest& m) {
  bool fpzip = m.codec.fpzip;
  for (const StoreVariable& v : m.variables) fpzip = fpzip || (v.codec && v.codec->fpzip);
  return fpzip ? kManifestVersionFpzip : kManifestVersionPredictors;
}

bool has_lossy_codec(const Manifest& m) {
  bool lossy = m.codec.zfp.has_value();
  for (const StoreVariable& v : m.variables) lossy = lossy || (v.codec && v.codec->zfp);
  return lossy;
}

bool needs_georeference_version(const Manifest& m) {
  return m.grid_mapping.has_value() || m.x.periodic || is_projection_kind(m.x.kind) ||
         is_projection_kind(m.y.kind);
}

bool needs_geometry_version(const Manifest& m) { return m.geometry.has_value(); }

std::uint32_t version_for_plan(const Manifest& m) {
  if (has_lossy_codec(m)) return kManifestVersionLossy;
  if (needs_geometry_version(m)) return kManifestVersionGeometry;
  return needs_georeference_version(m) ? kManifestVersionGeoreference : version_for_codecs(m);
}

std::string step_file_name(std::uint32_t step) { return fmt::format("steps/step-{:06d}.bricks", step); }

bool is_curvilinear(const Manifest& m) {
  return m.geometry && m.geometry->horizontal.kind == HorizontalGeometry::Kind::kCurvilinear;
}

bool has_geometry_file(const Manifest& m) {
  return is_curvilinear(m) || (m.geometry && m.geometry->surface);
}

namespace {

bool has_field(const Manifest& m, bool varies_in_time) {
  return m.geometry && m.geometry->vertical.kind == VerticalGeometry::Kind::kField &&
         m.geometry->vertical.varies_in_time == varies_in_time;
}

}  // namespace

bool has_geometry_bricks(const Manifest& m) { return has_field(m, false); }

std::uint32_t step_section_count(const Manifest& m) {
  return static_cast<std::uint32_t>(m.variables.size()) + (has_field(m, true) ? 1 : 0);
}

namespace {

// The format version a plan names must be able to hold what the plan holds, and need it.
void check_plan_version(const Manifest& m) {
  const std::uint32_t version = m.format_version;
  if (version == 0 || version > kManifestFormatVersion) {
    throw make_error(ErrorCode::kInvalidArgument, "cannot write manifest format version {}",
                     version);
  }
  if (version < kManifestVersionPredictors) {
    bool v2_only = m.codec.predictor != kPredictorNone;
    for (const StoreVariable& v : m.variables) v2_only = v2_only || v.codec.has_value();
    if (v2_only) {
      throw make_error(ErrorCode::kInvalidArgument,
                       "a version {} manifest cannot hold predictors or per-variable codecs",
                       version);
    }
  }
  if ((version >= kManifestVersionLossy) != has_lossy_codec(m)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "a version {} manifest {} a lossy (zfp) codec (version {} is for one)", version,
                     version < kManifestVersionLossy ? "cannot hold" : "needs", kManifestVersionLossy);
  }
  if (version >= kManifestVersionLossy) return;  // holds every earlier feature, or none
  if (version < kManifestVersionGeoreference &&
      (version >= kManifestVersionFpzip) != (version_for_codecs(m) >= kManifestVersionFpzip)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "a version {} manifest {} codecs with fpzip (version {} is for those)", version,
                     version < kManifestVersionFpzip ? "cannot hold" : "needs", kManifestVersionFpzip);
  }
  if ((version >= kManifestVersionGeometry) != needs_geometry_version(m)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "a version {} manifest {} a grid geometry (version {} is for one)", version,
                     version < kManifestVersionGeometry ? "cannot hold" : "needs",
                     kManifestVersionGeometry);
  }
  if (version < kManifestVersionGeometry &&
      (version >= kManifestVersionGeoreference) != needs_georeference_version(m)) {
    throw make_error(ErrorCode::kInvalidArgument,
                     "a version {} manifest {} a grid mapping, projection axes or a periodic "
                     "longitude (version {} is for those)",
                     version, version < kManifestVersionGeoreference ? "cannot hold" : "needs",
                     kManifestVersionGeoreference);
  }
}

// A curvilinear grid is placed by its coordinate arrays, not by a grid mapping, and its x
// and y are index axes (0 .. n-1); index axes belong to curvilinear grids only.
void check_curvilinear_grid(const Manifest& m, ErrorCode code, std::string_view what) {
  const bool curvilinear = is_curvilinear(m);
  if (m.z.kind == AxisKind::kIndex) {
    throw make_error(code, "{}: grid.z '{}' has kind 'index' (only x and y can)", what, m.z.name);
  }
  if ((m.x.kind == AxisKind::kIndex) != curvilinear || (m.y.kind == AxisKind::kIndex) != curvilinear) {
    throw make_error(code,
                     "{}: axes x '{}' ({}) and y '{}' ({}): index axes go with a curvilinear "
                     "geometry.horizontal, and only with one",
                     what, m.x.name, axis_kind_name(m.x.kind), m.y.name, axis_kind_name(m.y.kind));
  }
  for (const Axis* a : {&m.x, &m.y}) {
    for (std::size_t i = 0; curvilinear && i < a->values.size(); ++i) {
      if (a->values[i] != static_cast<double>(i)) {
        throw make_error(code, "{}: index axis '{}' holds {} at {} (must be 0, 1, ..., n-1)", what,
                         a->name, a->values[i], i);
      }
    }
  }
  if (curvilinear && m.grid_mapping) {
    throw make_error(code,
                     "{}: geometry.horizontal is curvilinear but the grid has a mapping ('{}'): "
                     "one of them places x and y",
                     what, m.grid_mapping->variable);
  }
}

json variable_json(const StoreVariable& v, std::uint32_t version) {
  json jv{{"name", v.name},
          {"units", v.units},
          {"long_name", v.long_name},
          {"standard_name", v.standard_name},
          {"dtype", std::string(dtype_name(v.dtype))},
          {"source_type", v.source_type}};
  // JSON has no NaN or Inf (nlohmann writes null, which no reader accepts). A
  // non-finite fill, missing value or bound is left out: it says nothing about the
  // stored samples (formats/store.md, "Manifest"). Packing attributes must be finite.
  auto put = [&](const char* key, const std::optional<double>& value) {
    if (value && std::isfinite(*value)) jv[key] = *value;
  };
  auto put_finite = [&](const char* key, const std::optional<double>& value) {
    if (value && !std::isfinite(*value)) {
      throw make_error(ErrorCode::kInvalidArgument, "variable '{}': {} {} is not finite", v.name,
                       key, *value);
    }
    put(key, value);
  };
  put("fill_value", v.fill_value);
  put("missing_value", v.missing_value);
  put("valid_min", v.valid_min);
  put("valid_max", v.valid_max);
  put_finite("scale_factor", v.scale_factor);
  put_finite("add_offset", v.add_offset);
  if (v.codec) jv["codec"] = codec_json(*v.codec, version);
  return jv;
}

json grid_json(const Manifest& m) {
  json grid{{"x", axis_json(m.x)}, {"y", axis_json(m.y)}, {"z", axis_json(m.z)}};
  if (m.grid_mapping) {
    grid["mapping"] = json{{"variable", m.grid_mapping->variable},
                           {"grid_mapping_name", m.grid_mapping->name},
                           {"attributes", m.grid_mapping->attributes},
                           {"proj", m.grid_mapping->proj}};
  }
  return grid;
}

}  // namespace

json manifest_plan_json(const Manifest& m) {
  check_plan_version(m);
  const std::uint32_t version = m.format_version;
  json vars = json::array();
  for (const StoreVariable& v : m.variables) vars.push_back(variable_json(v, version));
  json sources = json::array();
  for (const SourceRecord& s : m.sources) {
    sources.push_back(
        json{{"path", s.path}, {"size", s.size}, {"header_checksum", hex64(s.header_checksum)}});
  }
  const OctreeLayout layout(m.dims(), m.brick);
  check_curvilinear_grid(m, ErrorCode::kInvalidArgument, "manifest");
  json plan{
      {"format", "strielad-store"},
      {"format_version", version},
      {"grid", grid_json(m)},
      {"time", json{{"name", m.time.name},
                    {"units", m.time.units},
                    {"calendar", m.time.calendar},
                    {"values", m.time.values}}},
      {"variables", std::move(vars)},
      {"octree", json{{"brick", m.brick},
                      {"node_count", layout.node_count()},
                      {"levels", levels_json(layout)}}},
      {"codec", codec_json(m.codec, version)},
      {"nan_as_fill", m.nan_as_fill},
      {"sources", std::move(sources)},
  };
  if (m.geometry) plan["geometry"] = geometry_json(*m.geometry, m.z.size());
  return plan;
}

std::uint64_t compute_store_id(const Manifest& m) {
  const std::string plan = manifest_plan_json(m).dump();
  return checksum64(as_bytes_of(plan));
}

json manifest_to_json(const Manifest& m) {
  json j = manifest_plan_json(m);
  j["tool_version"] = m.tool_version;
  j["store_id"] = hex64(m.store_id);
  j["state"] = m.complete ? "complete" : "converting";
  if (m.complete) {
    json steps = json::array();
    for (const StepRecord& s : m.steps) {
      steps.push_back(json{{"step", s.step},
                           {"file", s.file},
                           {"size", s.size},
                           {"footer_checksum", hex64(s.footer_checksum)}});
    }
    j["steps"] = std::move(steps);
    j["summary"] = m.summary;
  }
  return j;
}

namespace {

GridMapping grid_mapping_from_json(const json& j, std::uint32_t version, std::string_view what) {
  const std::string where = fmt::format("{}: grid.mapping", what);
  if (version < kManifestVersionGeoreference) {
    throw make_error(ErrorCode::kCorrupt, "{}: needs format version {} (this is {})", where,
                     kManifestVersionGeoreference, version);
  }
  GridMapping gm;
  gm.variable = get<std::string>(j, "variable", where);
  gm.name = get<std::string>(j, "grid_mapping_name", where);
  gm.attributes = get<json>(j, "attributes", where);
  if (!gm.attributes.is_object()) {
    throw make_error(ErrorCode::kCorrupt, "{}: key 'attributes' is not an object", where);
  }
  gm.proj = get<std::string>(j, "proj", where);
  return gm;
}

// The axes and grid mapping, which must agree: projection axes in pairs, and with a PROJ
// string only.
void read_grid(const json& grid, std::uint32_t version, std::string_view what, Manifest& m) {
  m.x = axis_from_json(get<json>(grid, "x", what), fmt::format("{}: grid.x", what), version);
  m.y = axis_from_json(get<json>(grid, "y", what), fmt::format("{}: grid.y", what), version);
  m.z = axis_from_json(get<json>(grid, "z", what), fmt::format("{}: grid.z", what), version);
  if (m.y.periodic || m.z.periodic) {
    throw make_error(ErrorCode::kCorrupt, "{}: only the x axis can be periodic", what);
  }
  if (const auto it = grid.find("mapping"); it != grid.end()) {
    m.grid_mapping = grid_mapping_from_json(*it, version, what);
  }
  if ((m.x.kind == AxisKind::kProjectionX) != (m.y.kind == AxisKind::kProjectionY) ||
      (m.grid_mapping && !m.grid_mapping->proj.empty() && m.x.kind != AxisKind::kProjectionX)) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: axes x '{}' ({}) and y '{}' ({}) do not match the grid mapping", what,
                     m.x.name, axis_kind_name(m.x.kind), m.y.name, axis_kind_name(m.y.kind));
  }
}

TimeAxis time_from_json(const json& time, std::string_view what) {
  TimeAxis t;
  t.name = get<std::string>(time, "name", what);
  t.units = get<std::string>(time, "units", what);
  t.calendar = get<std::string>(time, "calendar", what);
  t.values = get<std::vector<double>>(time, "values", what);
  if (t.values.empty()) throw make_error(ErrorCode::kCorrupt, "{}: no time steps", what);
  return t;
}

StoreVariable variable_from_json(const json& jv, std::uint32_t version, std::string_view what) {
  StoreVariable v;
  v.name = get<std::string>(jv, "name", what);
  v.units = get<std::string>(jv, "units", what);
  v.long_name = get<std::string>(jv, "long_name", what);
  v.standard_name = get<std::string>(jv, "standard_name", what);
  v.dtype = dtype_from_name(get<std::string>(jv, "dtype", what));
  v.source_type = get<std::string>(jv, "source_type", what);
  v.fill_value = get_optional(jv, "fill_value", what);
  v.missing_value = get_optional(jv, "missing_value", what);
  v.valid_min = get_optional(jv, "valid_min", what);
  v.valid_max = get_optional(jv, "valid_max", what);
  v.scale_factor = get_optional(jv, "scale_factor", what);
  v.add_offset = get_optional(jv, "add_offset", what);
  if (const auto it = jv.find("codec"); it != jv.end()) {
    const std::string where = fmt::format("{}: variable '{}'", what, v.name);
    if (version < kManifestVersionPredictors) {
      throw make_error(ErrorCode::kCorrupt, "{}: key 'codec' needs format version {} (this is {})",
                       where, kManifestVersionPredictors, version);
    }
    v.codec = codec_from_json(*it, version, where);
  }
  return v;
}

// The geometry object: in version 5 and only there.
void read_geometry(const json& j, std::uint32_t version, std::string_view what, Manifest& m) {
  const auto it = j.find("geometry");
  if (version < kManifestVersionGeometry) {
    if (it != j.end()) {
      throw make_error(ErrorCode::kCorrupt, "{}: key 'geometry' needs format version {} (this is {})",
                       what, kManifestVersionGeometry, version);
    }
    return;
  }
  if (it == j.end()) {
    if (version >= kManifestVersionLossy) return;  // optional from version 6 on
    throw make_error(ErrorCode::kCorrupt,
                     "{}: format version {} but no key 'geometry' (a writer uses version {} or "
                     "below then)",
                     what, version, kManifestVersionGeoreference);
  }
  m.geometry = geometry_from_json(*it, m.z.size(), what);
  check_curvilinear_grid(m, ErrorCode::kCorrupt, what);
}

// A writer picks the lowest version that holds the content: a higher one is corrupt.
void check_version_needed(const Manifest& m, std::uint32_t version, std::string_view what) {
  if (version == kManifestVersionLossy && !has_lossy_codec(m)) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: format version {} but no codec has 'zfp' (a writer uses version {} or "
                     "below then)",
                     what, version, kManifestVersionGeometry);
  }
  if (version == kManifestVersionGeoreference && !needs_georeference_version(m)) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: format version {} but the grid has no grid mapping, projection axis or "
                     "periodic longitude (a writer uses version {} or below then)",
                     what, version, kManifestVersionFpzip);
  }
  if (version == kManifestVersionFpzip && version_for_codecs(m) < kManifestVersionFpzip) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: format version {} but no codec has 'fpzip' (a writer uses version {} then)",
                     what, version, kManifestVersionPredictors);
  }
}

// The recorded level table must match the one computed from grid and brick.
void check_level_table(const json& octree, const Manifest& m, std::string_view what) {
  try {
    const OctreeLayout layout(m.dims(), m.brick);
    if (get<json>(octree, "levels", what) != levels_json(layout) ||
        get<std::uint64_t>(octree, "node_count", what) != layout.node_count()) {
      throw make_error(ErrorCode::kCorrupt,
                       "{}: octree level table differs from the one computed for grid {}x{}x{} "
                       "and brick {}",
                       what, m.x.size(), m.y.size(), m.z.size(), m.brick);
    }
  } catch (const Error& e) {
    if (e.code() == ErrorCode::kCorrupt) throw;
    throw make_error(ErrorCode::kCorrupt, "{}: {}", what, e.what());
  }
}

// A complete store's step files (one per time step) and summary.
void read_completion(const json& j, std::string_view what, Manifest& m) {
  for (const json& js : get<json>(j, "steps", what)) {
    m.steps.push_back(StepRecord{
        get<std::uint32_t>(js, "step", what), get<std::string>(js, "file", what),
        get<std::uint64_t>(js, "size", what),
        parse_hex64(get<std::string>(js, "footer_checksum", what), "footer_checksum", what)});
  }
  if (m.steps.size() != m.time.values.size()) {
    throw make_error(ErrorCode::kCorrupt, "{}: complete store lists {} step files for {} steps",
                     what, m.steps.size(), m.time.values.size());
  }
  m.summary = get<json>(j, "summary", what);
}

}  // namespace

Manifest manifest_from_json(const json& j, std::string_view what) {
  if (!j.is_object()) throw make_error(ErrorCode::kCorrupt, "{}: payload is not a JSON object", what);
  if (get<std::string>(j, "format", what) != "strielad-store") {
    throw make_error(ErrorCode::kCorrupt, "{}: key 'format' is not \"strielad-store\"", what);
  }
  const auto version = get<std::uint32_t>(j, "format_version", what);
  check_version(version, what);
  Manifest m;
  m.format_version = version;
  m.tool_version = get<std::string>(j, "tool_version", what);
  m.store_id = parse_hex64(get<std::string>(j, "store_id", what), "store_id", what);
  const auto state = get<std::string>(j, "state", what);
  if (state != "complete" && state != "converting") {
    throw make_error(ErrorCode::kCorrupt, "{}: unknown state '{}'", what, state);
  }
  m.complete = state == "complete";
  read_grid(get<json>(j, "grid", what), version, what, m);
  read_geometry(j, version, what, m);
  m.time = time_from_json(get<json>(j, "time", what), what);
  for (const json& jv : get<json>(j, "variables", what)) {
    m.variables.push_back(variable_from_json(jv, version, what));
  }
  if (m.variables.empty()) throw make_error(ErrorCode::kCorrupt, "{}: no variables", what);
  const json& octree = get<json>(j, "octree", what);
  m.brick = get<std::uint32_t>(octree, "brick", what);
  m.codec = codec_from_json(get<json>(j, "codec", what), version, what);
  m.nan_as_fill = get<bool>(j, "nan_as_fill", what);
  check_version_needed(m, version, what);
  for (const json& js : get<json>(j, "sources", what)) {
    m.sources.push_back(SourceRecord{
        get<std::string>(js, "path", what), get<std::uint64_t>(js, "size", what),
        parse_hex64(get<std::string>(js, "header_checksum", what), "header_checksum", what)});
  }
  check_level_table(octree, m, what);
  if (m.complete) read_completion(j, what, m);
  if (compute_store_id(m) != m.store_id) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: store_id {:016x} does not match the manifest's content ({:016x})", what,
                     m.store_id, compute_store_id(m));
  }
  return m;
}

std::vector<std::byte> encode_manifest(const Manifest& m) {
  const std::string payload = manifest_to_json(m).dump(1);
  ByteWriter w;
  w.text(kManifestMagic);
  w.u32(m.format_version);
  w.u32(0);
  w.u64(payload.size());
  w.text(payload);
  w.u64(checksum64(w.data()));
  return w.take();
}

Manifest decode_manifest(std::span<const std::byte> bytes, std::string_view what) {
  ByteReader r(bytes, what);
  const auto magic = r.bytes(8, "magic");
  if (std::memcmp(magic.data(), kManifestMagic.data(), 8) != 0) {
    throw make_error(ErrorCode::kCorrupt, "{}: bad magic: not a STRIELAD manifest", what);
  }
  const std::uint32_t version = r.u32("format_version");
  check_version(version, what);
  if (const std::uint32_t flags = r.u32("flags"); flags != 0) {
    throw make_error(ErrorCode::kCorrupt, "{}: reserved flags are {} (must be 0)", what, flags);
  }
  const std::uint64_t payload_size = r.u64("payload_size");
  if (payload_size > bytes.size() || bytes.size() - kFrameHeader - kFrameTrailer != payload_size) {
    throw make_error(bytes.size() < kFrameHeader + kFrameTrailer + payload_size
                         ? ErrorCode::kTruncated
                         : ErrorCode::kCorrupt,
                     "{}: file is {} bytes but the header announces {} (payload {} + 32)", what,
                     bytes.size(), payload_size + kFrameHeader + kFrameTrailer, payload_size);
  }
  const auto payload = r.bytes(payload_size, "payload");
  const std::uint64_t stored = r.u64("checksum");
  const std::uint64_t computed = checksum64(bytes.first(kFrameHeader + payload_size));
  if (stored != computed) {
    throw make_error(ErrorCode::kCorrupt, "{}: checksum mismatch (stored {:016x}, computed {:016x})",
                     what, stored, computed);
  }
  json j;
  try {
    j = json::parse(reinterpret_cast<const char*>(payload.data()),
                    reinterpret_cast<const char*>(payload.data()) + payload.size());
  } catch (const json::exception& e) {
    throw make_error(ErrorCode::kCorrupt, "{}: payload is not valid JSON: {}", what, e.what());
  }
  Manifest m = manifest_from_json(j, what);
  if (m.format_version != version) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: the frame says format version {} but the payload says {}", what, version,
                     m.format_version);
  }
  return m;
}

}  // namespace strielad::format
