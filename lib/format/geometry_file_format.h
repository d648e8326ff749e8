// SPDX-License-Identifier: Apache-2.0
// The store's GEOMETRY file (formats/store.md, "Geometry file"): the level-0 2-D longitude
// and latitude of a curvilinear grid and the model's surface height, as checksummed,
// zstd-compressed float64 arrays. Pure encode/decode over bytes, no file I/O. Decoders
// throw strielad::Error (kCorrupt, kTruncated, kVersionTooNew) naming `what` and the field.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace strielad::format {

struct Manifest;

inline constexpr std::uint32_t kGeometryFileFormatVersion = 1;
inline constexpr std::size_t kGeometryHeaderSize = 64;
inline constexpr std::size_t kGeometryArrayEntrySize = 56;
inline constexpr std::uint32_t kGeometryMaxSide = 65536;

// Arrays of ny * nx values, i (along x) fastest. lon and lat are both empty when the
// grid is placed by its axes (a store with only a surface height).
struct HorizontalCoordinates {
  std::uint32_t nx = 0, ny = 0;
  std::vector<double> lon, lat;  // degrees east (unwrapped), degrees north
  std::optional<std::vector<double>> surface_m;  // m above mean sea level
  bool has_coordinates() const { return !lon.empty(); }
  friend bool operator==(const HorizontalCoordinates&, const HorizontalCoordinates&) = default;
};

struct GeometryFile {
  std::uint64_t store_id = 0;
  HorizontalCoordinates coordinates;
};

// XXH3 of the raw lon bytes followed by the raw lat bytes (little-endian float64): the
// manifest's geometry.horizontal.coordinates_checksum.
std::uint64_t coordinates_checksum(const HorizontalCoordinates& coordinates);

// Throws kInvalidArgument when the arrays break a rule a reader checks (sizes, finite
// values, latitudes, unwrapped longitudes).
std::vector<std::byte> encode_geometry_file(const GeometryFile& file);
GeometryFile decode_geometry_file(std::span<const std::byte> bytes, std::string_view what);

// The file must belong to the manifest: its store_id, nx and ny, the arrays its geometry
// needs, and the coordinates checksum. Throws kCorrupt naming `what` and the field.
void check_geometry_file_matches(const GeometryFile& file, const Manifest& manifest,
                                 std::string_view what);

}  // namespace strielad::format
