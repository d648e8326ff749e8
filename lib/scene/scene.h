// SPDX-License-Identifier: Apache-2.0
// The scene (formats/scene.md): which time step, which sub-volumes (scalar limits and a
// domain box) and which per-vertex attributes to extract. Parsing, validation and the
// canonical JSON form, then resolution of names against a store's manifest.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace strielad {

namespace format {
struct Manifest;
}

// Version of formats/scene.md this library reads and writes, and its size limits.
inline constexpr std::uint32_t kSceneFormatVersion = 4;
// The first version with slices, terrain, sun and trajectories (formats/scene.md,
// "Version history"); a scene using one of them must declare at least this version.
inline constexpr std::uint32_t kSceneVersionGeography = 2;
// The first version with geographic boxes in sub-volumes.
inline constexpr std::uint32_t kSceneVersionGeographicBox = 3;
// The first version with a height range in a geographic box.
inline constexpr std::uint32_t kSceneVersionGeographicHeight = 4;
inline constexpr std::size_t kMaxSceneBytes = 1u << 20;
inline constexpr std::size_t kMaxSceneNesting = 32;
inline constexpr std::size_t kMaxSubVolumes = 64;
inline constexpr std::size_t kMaxLimitsPerSubVolume = 16;
inline constexpr std::size_t kMaxSceneAttributes = 64;
inline constexpr std::uint32_t kMaxSubVolumeId = 65535;
inline constexpr std::size_t kMaxSubVolumeNameBytes = 256;
inline constexpr std::size_t kMaxSlices = 16;
inline constexpr std::uint32_t kMaxSliceId = 65535;

// The colour maps a slice may name (formats/scene.md, "Colour maps"), in documentation
// order; the first is the default.
inline constexpr std::array<std::string_view, 5> kSliceColormaps = {"viridis", "magma", "coolwarm",
                                                                    "greys", "turbo"};

// One scalar limit: min <= var <= max, inclusive; an absent bound is open.
struct Limit {
  std::string var;
  std::optional<double> min, max;
  friend bool operator==(const Limit&, const Limit&) = default;
};

// An inclusive coordinate range, lo <= hi whatever the axis's storage order.
struct AxisRange {
  double lo = 0, hi = 0;
  friend bool operator==(const AxisRange&, const AxisRange&) = default;
};

// A box in true longitude and latitude (format version 3), whatever the grid's axes: on
// a rotated-pole or projected grid it is not axis-aligned, and extraction evaluates it
// per sample (formats/scene.md, "Geographic boxes"). Longitudes in any convention.
// `height` (version 4): metres, the store's own heights (a height axis's, or the grid
// geometry's field on terrain-following levels, evaluated per sample).
struct GeographicBox {
  std::optional<AxisRange> lon, lat;  // degrees
  std::optional<AxisRange> height;    // metres; at least one of the three is present
  friend bool operator==(const GeographicBox&, const GeographicBox&) = default;
};

struct SubVolume {
  std::uint32_t id = 0;  // 1..65535, unique in the scene
  std::string name;      // label, at most 256 bytes
  std::vector<Limit> limits;
  std::map<std::string, AxisRange> domain;  // axis name -> range; absent axis = unbounded
  std::optional<GeographicBox> geographic = std::nullopt;  // version 3
  friend bool operator==(const SubVolume&, const SubVolume&) = default;
};

// A slice (format version 2): either the plane `axis` = value (an axis-aligned plane in
// the axis's units) or the iso-level where the field of `level_var` equals value;
// exactly one of `axis` and `level_var` is non-empty. Coloured by the field of `var`.
struct Slice {
  std::uint32_t id = 0;   // 1..65535, unique among the scene's slices
  std::string name{};       // label, at most 256 bytes
  std::string axis{};       // axis name of the store, or "" for a level slice
  std::string level_var{};  // variable of a level slice, or "" for an axis plane
  double value = 0;         // the plane's coordinate, or the level's value
  std::string var{};        // the variable that colours the slice
  std::string colormap = std::string(kSliceColormaps[0]);
  std::optional<AxisRange> range{};  // colour map [lo, hi], lo < hi; absent: the viewer's
  bool is_level() const { return !level_var.empty(); }
  friend bool operator==(const Slice&, const Slice&) = default;
};

// Terrain (format version 2): paths relative to the scene file, as written. Empty var /
// image: absent. The viewer uses it; a server keeps it in the canonical form only.
struct Terrain {
  std::string dem;
  std::string var;
  std::string image;
  friend bool operator==(const Terrain&, const Terrain&) = default;
};

// The sun (format version 2): the true sun at the simulation time, or a fixed direction.
struct Sun {
  bool from_time = true;     // {"mode": "time"}
  double elevation_deg = 0;  // fixed: -90..90 above the horizon
  double azimuth_deg = 0;    // fixed: 0..360, clockwise from north
  friend bool operator==(const Sun&, const Sun&) = default;
};

// Flight tracks (format version 2): a track file relative to the scene file and the
// window drawn before the current time.
struct Trajectories {
  std::string file;
  double minutes = 2;  // > 0
  friend bool operator==(const Trajectories&, const Trajectories&) = default;
};

struct Scene {
  std::uint32_t time = 0;  // index of the store's time step
  std::vector<SubVolume> subvolumes;
  std::vector<std::string> attributes;  // variables carried per vertex, in this order
  std::vector<Slice> slices;            // version 2: 0..16, in this order
  std::optional<Terrain> terrain;       // version 2
  std::optional<Sun> sun;               // version 2
  std::optional<Trajectories> trajectories;  // version 2
  // The format version the canonical form declares: the lowest that has every key used.
  std::uint32_t required_format_version() const {
    std::uint32_t version = 0;
    for (const SubVolume& sv : subvolumes) {
      if (sv.geographic && sv.geographic->height) return kSceneVersionGeographicHeight;
      if (sv.geographic) version = kSceneVersionGeographicBox;
    }
    if (version != 0) return version;
    return slices.empty() && !terrain && !sun && !trajectories ? 1 : kSceneVersionGeography;
  }
  friend bool operator==(const Scene&, const Scene&) = default;
};

// Parses and validates scene JSON (syntax, keys, types, limits; no store needed).
// `what` names the scene (its file name) in messages; every message also names the
// offending value's path, e.g. "scene.json: subvolumes[1].limits[0].min: ...".
// \error kInvalidInput for anything formats/scene.md says to reject;
// \error kVersionTooNew when format_version is greater than kSceneFormatVersion.
Scene parse_scene(std::string_view json_text, std::string_view what);

// Reads a scene file (refusing one larger than kMaxSceneBytes without reading it) and
// parses it; messages name the file.
// \error kNotFound when the file does not exist; kIo when it cannot be read;
// otherwise as parse_scene.
Scene load_scene_file(const std::filesystem::path& path);

// The rules of formats/scene.md that need no store, for scenes built in code (a viewer's
// panel). parse_scene and resolve_scene apply them.
// \error kInvalidInput naming `what` and the path of the offending value.
void validate_scene(const Scene& scene, std::string_view what);

// The canonical form (formats/scene.md, "Canonical form"): compact JSON that parses back
// to an equal Scene and is byte-identical when written again.
// \error kInvalidInput (as validate_scene, `what` = "scene") for an invalid scene.
std::string scene_to_json(const Scene& scene);

// A limit on a variable of the store: min <= value <= max, open bounds as -inf/+inf.
struct ResolvedLimit {
  std::uint32_t variable = 0;  // index into Manifest::variables
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  friend bool operator==(const ResolvedLimit&, const ResolvedLimit&) = default;
};

struct ResolvedSubVolume {
  std::uint32_t id = 0;
  std::string name;
  std::vector<ResolvedLimit> limits;
  // Per x, y, z of the manifest: the domain range, or [-inf, +inf] when the scene does
  // not name the axis. Not clamped to the grid's extent. On a longitude x axis the range
  // is in the scene's convention (grid/longitude_turns.h); a full turn or more is
  // [-inf, +inf].
  std::array<AxisRange, 3> box;
  // A geographic box on a grid whose axes are not longitude and latitude (a rotated-pole
  // or projected grid): evaluated per sample. On a longitude/latitude grid it is folded
  // into `box` instead.
  std::optional<GeographicBox> geographic = std::nullopt;
  // A geographic height range on terrain-following levels (the store's geometry field is
  // a height): evaluated per sample on that field. On a height axis it is folded into
  // `box` instead. Never has lon or lat.
  std::optional<AxisRange> geometry_height = std::nullopt;
  friend bool operator==(const ResolvedSubVolume&, const ResolvedSubVolume&) = default;
};

// A slice with names turned into indices (formats/scene.md, "Resolution against a
// store").
struct ResolvedSlice {
  std::uint32_t id = 0;
  std::string name;
  int axis = -1;                    // 0 x, 1 y, 2 z for an axis plane; -1 for a level slice
  std::uint32_t level_variable = 0; // level slices: the variable whose iso-level it is
  double value = 0;                 // the plane's coordinate, or the level's value
  std::uint32_t variable = 0;       // the colouring variable
  std::string colormap;
  std::optional<AxisRange> range;
  bool is_level() const { return axis < 0; }
  friend bool operator==(const ResolvedSlice&, const ResolvedSlice&) = default;
};

struct ResolvedScene {
  std::uint32_t time = 0;
  std::vector<ResolvedSubVolume> subvolumes;    // in scene order
  std::vector<ResolvedSlice> slices;            // in scene order
  std::vector<std::uint32_t> attributes;        // variable indices, in scene order
  // Sorted, distinct: limit variables, attributes, and the slices' level and colouring
  // variables.
  std::vector<std::uint32_t> needed_variables;
  friend bool operator==(const ResolvedScene&, const ResolvedScene&) = default;
};

// Validates the scene, then checks it against the store's manifest and turns names into
// indices (formats/scene.md, "Resolution against a store").
// \error kNotFound for a time step, variable or axis the store does not have (the
// message lists what it has); kInvalidInput for a domain range outside its axis's
// extent, a slice plane outside its axis's extent, and for whatever validate_scene
// rejects.
ResolvedScene resolve_scene(const Scene& scene, const format::Manifest& manifest,
                            std::string_view what);

}  // namespace strielad
