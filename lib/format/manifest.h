// SPDX-License-Identifier: Apache-2.0
// The store manifest (formats/store.md, "Manifest"): a JSON payload in a checksummed
// binary frame. Pure encode/decode, no file I/O.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "grid/axis.h"
#include "format/codec_spec.h"
#include "format/manifest_geometry.h"
#include "grid/grid_mapping.h"

namespace strielad::format {

// Manifest versions this code reads (1 to 6) and writes (2; 3 when a codec has fpzip; 4
// when the grid is placed by a grid mapping or goes round the Earth; 5 when it records a
// grid geometry; 6 when a codec is lossy, whatever else it holds): formats/store.md.
inline constexpr std::uint32_t kManifestFormatVersion = 6;
// The first version with georeferencing: a grid mapping (Manifest::grid_mapping),
// projection axis kinds and periodic longitude axes (Axis::periodic).
inline constexpr std::uint32_t kManifestVersionGeoreference = 4;
// The first version with a grid geometry (Manifest::geometry): curvilinear horizontal
// coordinates, terrain-following vertical levels, the model's surface height.
inline constexpr std::uint32_t kManifestVersionGeometry = 5;

struct StoreVariable {
  std::string name, units, long_name, standard_name;
  DType dtype = DType::kFloat32;
  std::string source_type;
  // As the source had them. A NaN or infinite fill_value, missing_value, valid_min or
  // valid_max is not written (JSON has no such numbers; the stored samples do not depend
  // on it), so it reads back absent; scale_factor and add_offset must be finite.
  std::optional<double> fill_value, missing_value, valid_min, valid_max, scale_factor, add_offset;
  // The variable's own codec (format version 2); absent: the store-wide Manifest::codec.
  std::optional<CodecSpec> codec = std::nullopt;
  friend bool operator==(const StoreVariable&, const StoreVariable&) = default;
};

struct SourceRecord {
  std::string path;
  std::uint64_t size = 0;
  std::uint64_t header_checksum = 0;
  friend bool operator==(const SourceRecord&, const SourceRecord&) = default;
};

struct StepRecord {
  std::uint32_t step = 0;
  std::string file;  // relative to the store directory
  std::uint64_t size = 0;
  std::uint64_t footer_checksum = 0;
  friend bool operator==(const StepRecord&, const StepRecord&) = default;
};

struct Manifest {
  // The version the manifest was decoded from, and is encoded as: a rewritten version-1
  // manifest (finalize of an old store) stays version 1, since its store_id and step
  // files depend on its plan. New plans are version 2, or 3 when a codec has fpzip
  // (version_for_codecs).
  std::uint32_t format_version = 2;
  std::string tool_version;
  std::uint64_t store_id = 0;
  bool complete = false;
  Axis x, y, z;
  // How x and y are placed on the Earth when they are map-projection coordinates
  // (format version 4); absent for longitude/latitude axes and for Cartesian grids.
  std::optional<GridMapping> grid_mapping;
  // Where the samples lie when the axes alone do not say (format version 5); absent for
  // every store the axes (and grid mapping) place.
  std::optional<GridGeometry> geometry;
  TimeAxis time;
  std::vector<StoreVariable> variables;
  std::uint32_t brick = 24;
  CodecSpec codec;  // store-wide; a variable's own codec overrides it
  bool nan_as_fill = false;
  std::vector<SourceRecord> sources;
  std::vector<StepRecord> steps;  // only when complete
  nlohmann::json summary = nlohmann::json::object();  // only when complete

  Dims3 dims() const { return Dims3{x.size(), y.size(), z.size()}; }
  // The codec chunks of variable `v` are written with: its own, else the store-wide one.
  const CodecSpec& codec_of(std::size_t v) const {
    const auto& own = variables.at(v).codec;
    return own ? *own : codec;
  }
  // Index of a variable by name; throws kNotFound listing the store's variables.
  std::size_t variable_index(std::string_view name) const;
};

// The version a new plan with these codecs is written as: 3 when any has fpzip, else 2.
std::uint32_t version_for_codecs(const Manifest& manifest);
// Whether some variable's codec (or the store-wide one) is lossy: zfp chunks, version 6.
bool has_lossy_codec(const Manifest& manifest);
// Whether the plan needs version 4: a grid mapping, a projection axis or a periodic axis.
bool needs_georeference_version(const Manifest& manifest);
// Whether the plan needs version 5: a grid geometry.
bool needs_geometry_version(const Manifest& manifest);
// The version a new plan is written as: 6 with a lossy codec, else 5 or 4 when it needs
// it, else version_for_codecs.
std::uint32_t version_for_plan(const Manifest& manifest);

// Path of a step file relative to the store directory: "steps/step-000042.bricks".
std::string step_file_name(std::uint32_t step);
// Files of a store with a geometry (formats/store.md): the 2-D coordinates and surface
// height, and the time-invariant geometry field in the step-file layout.
inline constexpr std::string_view kGeometryFileName = "GEOMETRY";
inline constexpr std::string_view kGeometryBricksFileName = "geometry.bricks";
// Whether the grid is curvilinear: placed by the 2-D longitudes and latitudes of its
// GEOMETRY file, its x and y index axes.
bool is_curvilinear(const Manifest& manifest);
// Whether the store has a GEOMETRY file: a curvilinear grid or a surface height.
bool has_geometry_file(const Manifest& manifest);
// Whether the store has geometry.bricks: a vertical field that does not vary in time.
bool has_geometry_bricks(const Manifest& manifest);
// The sections of each step file: one per variable, plus the vertical field when it
// varies in time (section V, after the variables).
std::uint32_t step_section_count(const Manifest& manifest);

// The plan: everything that defines the store's content (formats/store.md), as the
// manifest's format_version writes it. Throws kInvalidArgument when a version-1
// manifest uses a version-2 feature (a predictor other than none, a variable's codec).
nlohmann::json manifest_plan_json(const Manifest& manifest);
std::uint64_t compute_store_id(const Manifest& manifest);

nlohmann::json manifest_to_json(const Manifest& manifest);
// Validates keys, types, axes, codecs and the octree level table; throws kCorrupt naming
// the key, kVersionTooNew for a format_version above kManifestFormatVersion.
Manifest manifest_from_json(const nlohmann::json& json, std::string_view what);

// Writes the frame and JSON with manifest.format_version (1 to 6).
std::vector<std::byte> encode_manifest(const Manifest& manifest);
// Reads versions 1 to 6; the frame's and the JSON's format_version must agree.
Manifest decode_manifest(std::span<const std::byte> bytes, std::string_view what);

}  // namespace strielad::format
