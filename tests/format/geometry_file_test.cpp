// SPDX-License-Identifier: Apache-2.0
// The GEOMETRY file: 2-D lon/lat and surface height round-trip exactly; every truncation,
// damaged byte, size, order and value rule is refused naming the file and the field; the
// file must match its manifest's geometry record.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>

#include "core/byte_io.h"
#include "core/checksum.h"
#include "format/geometry_file_format.h"
#include "format/manifest.h"
#include "support/expect_error.h"

namespace strielad::format {
namespace {

using testing::expect_error;

// A sheared 4 x 3 lattice that crosses the antimeridian (unwrapped past 180).
HorizontalCoordinates sheared(bool with_surface = true) {
  HorizontalCoordinates c;
  c.nx = 4;
  c.ny = 3;
  for (std::uint32_t j = 0; j < c.ny; ++j) {
    for (std::uint32_t i = 0; i < c.nx; ++i) {
      c.lon.push_back(178.5 + 0.75 * i + 0.1 * j);
      c.lat.push_back(60.0 + 0.5 * j - 0.05 * i);
    }
  }
  if (with_surface) {
    c.surface_m.emplace();
    for (std::size_t k = 0; k < 12; ++k) c.surface_m->push_back(std::sin(0.3 * k) * 1500.0);
  }
  return c;
}

std::vector<std::byte> encoded(const HorizontalCoordinates& c, std::uint64_t store_id = 42) {
  return encode_geometry_file(GeometryFile{store_id, c});
}

GeometryFile decoded(std::span<const std::byte> bytes) {
  return decode_geometry_file(bytes, "GEOMETRY");
}

// A file with uncompressed arrays, laid out by hand: `values[k]` for array id `ids[k]`;
// `edit` may change the table before it is sealed.
std::vector<std::byte> hand_made(std::uint32_t nx, std::uint32_t ny,
                                 const std::vector<std::uint32_t>& ids,
                                 const std::vector<std::vector<double>>& values,
                                 const std::function<void(std::vector<std::byte>&)>& edit = {}) {
  ByteWriter w;
  w.text("STRLDGEO");
  w.u32(1);
  w.u32(static_cast<std::uint32_t>(ids.size()));
  w.u64(42);
  w.u32(nx);
  w.u32(ny);
  w.zeros(24);
  w.u64(checksum64(w.data()));
  ByteWriter table;
  std::uint64_t offset = 64 + 56 * ids.size() + 8;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const auto raw = std::as_bytes(std::span(values[k]));
    table.u32(ids[k]);
    table.u32(0);
    table.u64(offset);
    table.u64(raw.size());
    table.u64(raw.size());
    table.u64(checksum64(raw));
    table.u64(checksum64(raw));
    table.u64(0);
    offset += raw.size();
  }
  std::vector<std::byte> t = table.take();
  if (edit) edit(t);
  w.bytes(t);
  w.u64(checksum64(t));
  for (const auto& v : values) w.bytes(std::as_bytes(std::span(v)));
  return w.take();
}

void reseal_header(std::vector<std::byte>& bytes) {
  const std::uint64_t sum = checksum64(std::span(bytes).first(56));
  std::memcpy(bytes.data() + 56, &sum, 8);
}

TEST(GeometryFileTest, RoundTripsCoordinatesAndSurfaceExactly) {
  for (const HorizontalCoordinates& c : {sheared(true), sheared(false)}) {
    const GeometryFile back = decoded(encoded(c, 0x1234));
    EXPECT_EQ(back.store_id, 0x1234u);
    EXPECT_EQ(back.coordinates, c);
  }
  HorizontalCoordinates surface_only = sheared(true);
  surface_only.lon.clear();
  surface_only.lat.clear();
  EXPECT_EQ(decoded(encoded(surface_only)).coordinates, surface_only);
  // Uncompressed arrays are read too.
  const HorizontalCoordinates c = sheared(true);
  EXPECT_EQ(decoded(hand_made(4, 3, {0, 1, 2}, {c.lon, c.lat, *c.surface_m})).coordinates, c);
}

TEST(GeometryFileTest, EncodingIsDeterministic) {
  EXPECT_EQ(encoded(sheared()), encoded(sheared()));
}

TEST(GeometryFileTest, EveryTruncationIsRefused) {
  const std::vector<std::byte> bytes = encoded(sheared());
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    try {
      decoded(std::span(bytes).first(n));
      ADD_FAILURE() << "a file cut to " << n << " bytes was read";
    } catch (const Error& e) {
      EXPECT_TRUE(e.code() == ErrorCode::kTruncated || e.code() == ErrorCode::kCorrupt)
          << n << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find("GEOMETRY"), std::string::npos) << e.what();
    }
  }
}

TEST(GeometryFileTest, EveryDamagedByteIsRefused) {
  const std::vector<std::byte> good = encoded(sheared());
  for (std::size_t k = 0; k < good.size(); ++k) {
    std::vector<std::byte> bad = good;
    bad[k] ^= std::byte{0x10};
    try {
      decoded(bad);
      ADD_FAILURE() << "a file with byte " << k << " damaged was read";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("GEOMETRY"), std::string::npos) << e.what();
    }
  }
  std::vector<std::byte> longer = good;
  longer.push_back(std::byte{0});
  expect_error([&] { decoded(longer); }, ErrorCode::kCorrupt, {"GEOMETRY", "1 bytes after the last array"});
}

TEST(GeometryFileTest, ChecksumsNameTheStructure) {
  std::vector<std::byte> bytes = encoded(sheared());
  bytes[30] ^= std::byte{1};  // ny
  expect_error([&] { decoded(bytes); }, ErrorCode::kCorrupt, {"GEOMETRY", "header checksum mismatch"});
  bytes = encoded(sheared());
  bytes[64 + 16] ^= std::byte{1};  // stored_size of lon
  expect_error([&] { decoded(bytes); }, ErrorCode::kCorrupt, {"array table checksum mismatch"});
  bytes = encoded(sheared());
  bytes.back() ^= std::byte{1};
  expect_error([&] { decoded(bytes); }, ErrorCode::kCorrupt, {"array 'surface'", "stored checksum mismatch"});
}

TEST(GeometryFileTest, HeaderFieldsAreChecked) {
  std::vector<std::byte> bytes = encoded(sheared());
  bytes[0] = std::byte{'X'};
  expect_error([&] { decoded(bytes); }, ErrorCode::kCorrupt, {"GEOMETRY", "bad magic"});
  bytes = encoded(sheared());
  bytes[8] = std::byte{2};
  expect_error([&] { decoded(bytes); }, ErrorCode::kVersionTooNew,
               {"GEOMETRY", "version 2 is newer than this reader (max 1)"});
  bytes = encoded(sheared());
  bytes[40] = std::byte{1};
  reseal_header(bytes);
  expect_error([&] { decoded(bytes); }, ErrorCode::kCorrupt, {"reserved"});
  bytes = encoded(sheared());
  bytes[12] = std::byte{4};
  reseal_header(bytes);
  expect_error([&] { decoded(bytes); }, ErrorCode::kCorrupt, {"array_count 4"});
  bytes = encoded(sheared());
  std::memset(bytes.data() + 24, 0, 4);
  reseal_header(bytes);
  expect_error([&] { decoded(bytes); }, ErrorCode::kCorrupt, {"grid 0 x 3"});
}

TEST(GeometryFileTest, ArraySizesOrderAndPlacesAreChecked) {
  const HorizontalCoordinates c = sheared(true);
  // A header that says 4 x 2: the arrays' raw_size is wrong.
  expect_error([&] { decoded(hand_made(4, 2, {0, 1, 2}, {c.lon, c.lat, *c.surface_m})); },
               ErrorCode::kCorrupt, {"array 'lon'", "raw_size 96 is not 8 * nx * ny = 64"});
  expect_error([&] { decoded(hand_made(4, 3, {1, 0}, {c.lat, c.lon})); }, ErrorCode::kCorrupt,
               {"array table entry 0 is array 1", "'lon'"});
  expect_error([&] { decoded(hand_made(4, 3, {0, 1}, {c.lon, c.lat}, [](auto& t) { t[4] = std::byte{7}; })); },
               ErrorCode::kCorrupt, {"array 'lon'", "unknown codec 7"});
  expect_error([&] { decoded(hand_made(4, 3, {0, 1}, {c.lon, c.lat}, [](auto& t) { t[56 + 8] ^= std::byte{8}; })); },
               ErrorCode::kCorrupt, {"array 'lat'", "is not where the previous part ends"});
  expect_error([&] { decoded(hand_made(4, 3, {2}, {*c.surface_m}, [](auto& t) { t[48] = std::byte{1}; })); },
               ErrorCode::kCorrupt, {"reserved field is 1"});
}

TEST(GeometryFileTest, ValuesAreChecked) {
  HorizontalCoordinates c = sheared(true);
  std::vector<double> lat = c.lat;
  lat[5] = std::nan("");
  expect_error([&] { decoded(hand_made(4, 3, {0, 1}, {c.lon, lat})); }, ErrorCode::kCorrupt,
               {"GEOMETRY", "lat at i 1, j 1 is not finite"});
  lat[5] = 90.5;
  expect_error([&] { decoded(hand_made(4, 3, {0, 1}, {c.lon, lat})); }, ErrorCode::kCorrupt,
               {"lat 90.5 at i 1, j 1 is outside [-90, 90]"});
  std::vector<double> lon = c.lon;
  lon[6] -= 360;  // wrapped instead of unwrapped
  expect_error([&] { decoded(hand_made(4, 3, {0, 1}, {lon, c.lat})); }, ErrorCode::kCorrupt,
               {"lon jumps by 180 degrees or more at i 2, j 1"});
  std::vector<double> surface = *c.surface_m;
  surface[0] = INFINITY;
  expect_error([&] { decoded(hand_made(4, 3, {2}, {surface})); }, ErrorCode::kCorrupt,
               {"surface at i 0, j 0 is not finite"});
  // Writers refuse what readers refuse.
  c.lat[0] = -91;
  expect_error([&] { encoded(c); }, ErrorCode::kInvalidArgument, {"outside [-90, 90]"});
  c = sheared(false);
  c.lat.pop_back();
  expect_error([&] { encoded(c); }, ErrorCode::kInvalidArgument, {"lon has 12 values and lat 11"});
}

Manifest manifest_for(const HorizontalCoordinates& c) {
  Manifest m;
  m.tool_version = "test";
  m.x = Axis{"west_east", AxisKind::kIndex, "1", "", "", "", {0, 1, 2, 3}};
  m.y = Axis{"south_north", AxisKind::kIndex, "1", "", "", "", {0, 1, 2}};
  m.z = Axis{"lev", AxisKind::kModelLevel, "1", "", "", "", {1, 2}};
  m.time = TimeAxis{"time", "hours since 2000-01-01", "standard", {0}};
  StoreVariable v;
  v.name = "ta";
  m.variables.push_back(v);
  GridGeometry g;
  g.horizontal = HorizontalGeometry{HorizontalGeometry::Kind::kCurvilinear, "XLONG", "XLAT",
                                    coordinates_checksum(c)};
  g.surface = SurfaceGeometry{"HGT", "m"};
  m.geometry = g;
  m.format_version = version_for_plan(m);
  m.store_id = compute_store_id(m);
  return m;
}

TEST(GeometryFileTest, FileMustMatchItsManifest) {
  const HorizontalCoordinates c = sheared(true);
  const Manifest m = manifest_for(c);
  const GeometryFile good = decoded(encoded(c, m.store_id));
  check_geometry_file_matches(good, m, "GEOMETRY");

  GeometryFile other = good;
  other.store_id ^= 1;
  expect_error([&] { check_geometry_file_matches(other, m, "GEOMETRY"); }, ErrorCode::kCorrupt,
               {"GEOMETRY", "store_id"});
  other = good;
  other.coordinates.lat[3] += 1e-9;
  expect_error([&] { check_geometry_file_matches(other, m, "GEOMETRY"); }, ErrorCode::kCorrupt,
               {"coordinates checksum", "geometry.horizontal.coordinates_checksum"});
  other = good;
  other.coordinates.surface_m.reset();
  expect_error([&] { check_geometry_file_matches(other, m, "GEOMETRY"); }, ErrorCode::kCorrupt,
               {"no surface", "geometry has curvilinear coordinates and surface"});
  Manifest wider = m;
  wider.x.values.push_back(4);
  expect_error([&] { check_geometry_file_matches(good, wider, "GEOMETRY"); }, ErrorCode::kCorrupt,
               {"grid 4 x 3 is not the manifest's 5 x 3"});
}

}  // namespace
}  // namespace strielad::format
