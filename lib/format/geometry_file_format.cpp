// SPDX-License-Identifier: Apache-2.0
#include "format/geometry_file_format.h"

#include <zstd.h>

#include <array>
#include <cmath>
#include <cstring>
#include <string>

#include "core/byte_io.h"
#include "core/checksum.h"
#include "core/error.h"
#include "format/manifest.h"

namespace strielad::format {
namespace {

constexpr std::string_view kGeometryMagic = "STRLDGEO";
constexpr std::array<std::string_view, 3> kArrayNames = {"lon", "lat", "surface"};
enum : std::uint32_t { kLon = 0, kLat = 1, kSurface = 2 };
enum : std::uint32_t { kCodecRaw = 0, kCodecZstd = 1 };

std::span<const std::byte> raw_bytes(const std::vector<double>& values) {
  return std::as_bytes(std::span(values));
}

// The rules every array set follows, for writers (kInvalidArgument) and readers (kCorrupt).
void check_arrays(const HorizontalCoordinates& c, ErrorCode code, std::string_view what) {
  if (c.nx < 1 || c.ny < 1 || c.nx > kGeometryMaxSide || c.ny > kGeometryMaxSide) {
    throw make_error(code, "{}: grid {} x {} is not within 1 to {} on each side", what, c.nx, c.ny,
                     kGeometryMaxSide);
  }
  const std::size_t n = std::size_t{c.nx} * c.ny;
  if (c.lon.size() != c.lat.size() || (!c.lon.empty() && c.lon.size() != n)) {
    throw make_error(code, "{}: lon has {} values and lat {}, for a grid of {} x {}", what,
                     c.lon.size(), c.lat.size(), c.nx, c.ny);
  }
  if (c.surface_m && c.surface_m->size() != n) {
    throw make_error(code, "{}: surface has {} values for a grid of {} x {}", what,
                     c.surface_m->size(), c.nx, c.ny);
  }
  if (c.lon.empty() && !c.surface_m) throw make_error(code, "{}: holds no array", what);
  auto check_finite = [&](const std::vector<double>& values, std::string_view name) {
    for (std::size_t k = 0; k < values.size(); ++k) {
      if (!std::isfinite(values[k])) {
        throw make_error(code, "{}: {} at i {}, j {} is not finite", what, name, k % c.nx,
                         k / c.nx);
      }
    }
  };
  check_finite(c.lon, "lon");
  check_finite(c.lat, "lat");
  if (c.surface_m) check_finite(*c.surface_m, "surface");
  for (std::size_t k = 0; k < c.lat.size(); ++k) {
    if (c.lat[k] < -90 || c.lat[k] > 90) {
      throw make_error(code, "{}: lat {} at i {}, j {} is outside [-90, 90]", what, c.lat[k],
                       k % c.nx, k / c.nx);
    }
  }
  for (std::size_t k = 0; k < c.lon.size(); ++k) {
    const std::size_t i = k % c.nx, j = k / c.nx;
    const bool jump_i = i > 0 && std::fabs(c.lon[k] - c.lon[k - 1]) >= 180;
    const bool jump_j = j > 0 && std::fabs(c.lon[k] - c.lon[k - c.nx]) >= 180;
    if (jump_i || jump_j) {
      throw make_error(code,
                       "{}: lon jumps by 180 degrees or more at i {}, j {} (longitudes must be "
                       "unwrapped)",
                       what, i, j);
    }
  }
}

std::vector<std::byte> zstd_compress(std::span<const std::byte> raw) {
  std::vector<std::byte> out(ZSTD_compressBound(raw.size()));
  const std::size_t n = ZSTD_compress(out.data(), out.size(), raw.data(), raw.size(), 3);
  if (ZSTD_isError(n)) {
    throw make_error(ErrorCode::kInternal, "zstd compression of a geometry array failed: {}",
                     ZSTD_getErrorName(n));
  }
  out.resize(n);
  return out;
}

struct ArrayEntry {
  std::uint32_t array = 0, codec = kCodecZstd;
  std::uint64_t offset = 0, stored_size = 0, raw_size = 0, stored_checksum = 0, raw_checksum = 0;
};

std::vector<std::uint32_t> arrays_of(const HorizontalCoordinates& c) {
  std::vector<std::uint32_t> ids;
  if (c.has_coordinates()) ids = {kLon, kLat};
  if (c.surface_m) ids.push_back(kSurface);
  return ids;
}

const std::vector<double>& array_values(const HorizontalCoordinates& c, std::uint32_t id) {
  return id == kLon ? c.lon : id == kLat ? c.lat : *c.surface_m;
}

std::vector<double>& array_values(HorizontalCoordinates& c, std::uint32_t id) {
  if (id == kSurface) c.surface_m.emplace();
  return id == kLon ? c.lon : id == kLat ? c.lat : *c.surface_m;
}

ArrayEntry read_entry(ByteReader& r) {
  ArrayEntry e;
  e.array = r.u32("array");
  e.codec = r.u32("codec");
  e.offset = r.u64("offset");
  e.stored_size = r.u64("stored_size");
  e.raw_size = r.u64("raw_size");
  e.stored_checksum = r.u64("stored_checksum");
  e.raw_checksum = r.u64("raw_checksum");
  if (const std::uint64_t reserved = r.u64("reserved"); reserved != 0) {
    throw make_error(ErrorCode::kCorrupt, "array table entry: reserved field is {} (must be 0)",
                     reserved);
  }
  return e;
}

// Checks the entry's place and sizes, its stored checksum, decompresses and checks the
// raw checksum.
std::vector<double> read_array(std::span<const std::byte> bytes, const ArrayEntry& e,
                               std::uint64_t expected_offset, std::uint64_t raw_size,
                               std::string_view where) {
  if (e.codec != kCodecRaw && e.codec != kCodecZstd) {
    throw make_error(ErrorCode::kCorrupt, "{}: unknown codec {} (0 raw, 1 zstd)", where, e.codec);
  }
  if (e.raw_size != raw_size) {
    throw make_error(ErrorCode::kCorrupt, "{}: raw_size {} is not 8 * nx * ny = {}", where,
                     e.raw_size, raw_size);
  }
  if (e.offset != expected_offset) {
    throw make_error(ErrorCode::kCorrupt, "{}: offset {} is not where the previous part ends ({})",
                     where, e.offset, expected_offset);
  }
  if (e.stored_size > bytes.size() - e.offset) {
    throw make_error(ErrorCode::kTruncated,
                     "{}: {} stored bytes at offset {} run past the end of the file ({} bytes)",
                     where, e.stored_size, e.offset, bytes.size());
  }
  const auto stored = bytes.subspan(e.offset, e.stored_size);
  if (const std::uint64_t sum = checksum64(stored); sum != e.stored_checksum) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: stored checksum mismatch (stored {:016x}, computed {:016x})", where,
                     e.stored_checksum, sum);
  }
  // The sizes are checked before the array is allocated.
  if (e.codec == kCodecRaw && e.stored_size != raw_size) {
    throw make_error(ErrorCode::kCorrupt, "{}: uncompressed but {} stored bytes for {}", where,
                     e.stored_size, raw_size);
  }
  if (e.codec == kCodecZstd) {
    const unsigned long long frame = ZSTD_getFrameContentSize(stored.data(), stored.size());
    if (frame == ZSTD_CONTENTSIZE_ERROR || frame != raw_size) {
      throw make_error(ErrorCode::kCorrupt, "{}: not a zstd frame of {} bytes", where, raw_size);
    }
  }
  std::vector<double> values(raw_size / 8);
  const auto out = std::as_writable_bytes(std::span(values));
  if (e.codec == kCodecRaw) {
    std::memcpy(out.data(), stored.data(), raw_size);
  } else {
    const std::size_t n = ZSTD_decompress(out.data(), out.size(), stored.data(), stored.size());
    if (ZSTD_isError(n) || n != raw_size) {
      throw make_error(ErrorCode::kCorrupt, "{}: zstd: {}", where,
                       ZSTD_isError(n) ? ZSTD_getErrorName(n) : "wrong size");
    }
  }
  if (const std::uint64_t sum = checksum64(out); sum != e.raw_checksum) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: raw checksum mismatch (stored {:016x}, computed {:016x})", where,
                     e.raw_checksum, sum);
  }
  return values;
}

}  // namespace

std::uint64_t coordinates_checksum(const HorizontalCoordinates& c) {
  std::vector<std::byte> both(raw_bytes(c.lon).begin(), raw_bytes(c.lon).end());
  both.insert(both.end(), raw_bytes(c.lat).begin(), raw_bytes(c.lat).end());
  return checksum64(both);
}

std::vector<std::byte> encode_geometry_file(const GeometryFile& file) {
  const HorizontalCoordinates& c = file.coordinates;
  check_arrays(c, ErrorCode::kInvalidArgument, "GEOMETRY");
  const std::vector<std::uint32_t> ids = arrays_of(c);
  ByteWriter w;
  w.text(kGeometryMagic);
  w.u32(kGeometryFileFormatVersion);
  w.u32(static_cast<std::uint32_t>(ids.size()));
  w.u64(file.store_id);
  w.u32(c.nx);
  w.u32(c.ny);
  w.zeros(24);
  w.u64(checksum64(w.data()));

  std::vector<std::vector<std::byte>> stored;
  std::uint64_t offset = kGeometryHeaderSize + kGeometryArrayEntrySize * ids.size() + 8;
  ByteWriter table;
  for (std::uint32_t id : ids) {
    const auto raw = raw_bytes(array_values(c, id));
    stored.push_back(zstd_compress(raw));
    table.u32(id);
    table.u32(kCodecZstd);
    table.u64(offset);
    table.u64(stored.back().size());
    table.u64(raw.size());
    table.u64(checksum64(stored.back()));
    table.u64(checksum64(raw));
    table.u64(0);
    offset += stored.back().size();
  }
  w.bytes(table.data());
  w.u64(checksum64(table.data()));
  for (const auto& s : stored) w.bytes(s);
  return w.take();
}

GeometryFile decode_geometry_file(std::span<const std::byte> bytes, std::string_view what) {
  ByteReader r(bytes, what);
  const auto magic = r.bytes(8, "magic");
  if (std::memcmp(magic.data(), kGeometryMagic.data(), 8) != 0) {
    throw make_error(ErrorCode::kCorrupt, "{}: bad magic: not a STRIELAD geometry file", what);
  }
  const std::uint32_t version = r.u32("format_version");
  if (version > kGeometryFileFormatVersion) {
    throw make_error(ErrorCode::kVersionTooNew,
                     "{}: format version {} is newer than this reader (max {})", what, version,
                     kGeometryFileFormatVersion);
  }
  if (version == 0) throw make_error(ErrorCode::kCorrupt, "{}: format version 0 is invalid", what);
  const std::uint32_t array_count = r.u32("array_count");
  GeometryFile file;
  file.store_id = r.u64("store_id");
  HorizontalCoordinates& c = file.coordinates;
  c.nx = r.u32("nx");
  c.ny = r.u32("ny");
  for (int k = 0; k < 3; ++k) {
    if (const std::uint64_t reserved = r.u64("reserved"); reserved != 0) {
      throw make_error(ErrorCode::kCorrupt, "{}: header reserved bytes are not zero", what);
    }
  }
  const std::uint64_t header_checksum = r.u64("header_checksum");
  if (const std::uint64_t sum = checksum64(bytes.first(56)); sum != header_checksum) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: header checksum mismatch (stored {:016x}, computed {:016x})", what,
                     header_checksum, sum);
  }
  if (array_count < 1 || array_count > 3) {
    throw make_error(ErrorCode::kCorrupt, "{}: array_count {} is not 1, 2 or 3", what, array_count);
  }
  if (c.nx < 1 || c.ny < 1 || c.nx > kGeometryMaxSide || c.ny > kGeometryMaxSide) {
    throw make_error(ErrorCode::kCorrupt, "{}: grid {} x {} is not within 1 to {} on each side",
                     what, c.nx, c.ny, kGeometryMaxSide);
  }
  const auto table = r.bytes(kGeometryArrayEntrySize * array_count, "array table");
  const std::uint64_t table_checksum = r.u64("table_checksum");
  if (const std::uint64_t sum = checksum64(table); sum != table_checksum) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: array table checksum mismatch (stored {:016x}, computed {:016x})", what,
                     table_checksum, sum);
  }
  static constexpr std::uint32_t kSets[4][3] = {{}, {kSurface}, {kLon, kLat}, {kLon, kLat, kSurface}};
  ByteReader entries(table, what);
  const std::uint64_t raw_size = std::uint64_t{8} * c.nx * c.ny;
  std::uint64_t offset = r.offset();
  for (std::uint32_t k = 0; k < array_count; ++k) {
    ArrayEntry e;
    try {
      e = read_entry(entries);
    } catch (const Error& err) {
      throw make_error(err.code(), "{}: {}", what, err.what());
    }
    if (e.array != kSets[array_count][k]) {
      throw make_error(ErrorCode::kCorrupt,
                       "{}: array table entry {} is array {}, but a file of {} arrays has '{}' "
                       "there",
                       what, k, e.array, array_count, kArrayNames[kSets[array_count][k]]);
    }
    const std::string where = fmt::format("{}: array '{}'", what, kArrayNames[e.array]);
    array_values(c, e.array) = read_array(bytes, e, offset, raw_size, where);
    offset += e.stored_size;
  }
  if (offset != bytes.size()) {
    throw make_error(ErrorCode::kCorrupt, "{}: {} bytes after the last array", what,
                     bytes.size() - offset);
  }
  check_arrays(c, ErrorCode::kCorrupt, what);
  return file;
}

void check_geometry_file_matches(const GeometryFile& file, const Manifest& m,
                                 std::string_view what) {
  const HorizontalCoordinates& c = file.coordinates;
  if (file.store_id != m.store_id) {
    throw make_error(ErrorCode::kCorrupt, "{}: store_id {:016x} is not the manifest's {:016x}",
                     what, file.store_id, m.store_id);
  }
  if (c.nx != m.x.size() || c.ny != m.y.size()) {
    throw make_error(ErrorCode::kCorrupt, "{}: grid {} x {} is not the manifest's {} x {}", what,
                     c.nx, c.ny, m.x.size(), m.y.size());
  }
  const bool curvilinear = is_curvilinear(m);
  const bool surface = m.geometry && m.geometry->surface.has_value();
  if (c.has_coordinates() != curvilinear || c.surface_m.has_value() != surface) {
    throw make_error(ErrorCode::kCorrupt,
                     "{}: holds {}lon/lat and {}surface, but the manifest's geometry has {}"
                     "curvilinear coordinates and {}surface",
                     what, c.has_coordinates() ? "" : "no ", c.surface_m ? "" : "no ",
                     curvilinear ? "" : "no ", surface ? "" : "no ");
  }
  if (curvilinear) {
    const std::uint64_t sum = coordinates_checksum(c);
    if (sum != m.geometry->horizontal.coordinates_checksum) {
      throw make_error(ErrorCode::kCorrupt,
                       "{}: coordinates checksum {:016x} is not the manifest's "
                       "geometry.horizontal.coordinates_checksum {:016x}",
                       what, sum, m.geometry->horizontal.coordinates_checksum);
    }
  }
}

}  // namespace strielad::format
