// SPDX-License-Identifier: Apache-2.0
// Fuzzes the GEOMETRY file decoder: header, array table, zstd arrays and value rules. The
// header and table checksums are re-sealed so that mutations reach the later checks.
#include <cmath>
#include <cstring>

#include "core/checksum.h"
#include "core/error.h"
#include "format/geometry_file_format.h"
#include "fuzz/fuzz_target.h"

using namespace strielad;
using namespace strielad::format;

namespace {

std::vector<std::uint8_t> to_u8(const std::vector<std::byte>& b) {
  return {reinterpret_cast<const std::uint8_t*>(b.data()),
          reinterpret_cast<const std::uint8_t*>(b.data()) + b.size()};
}

void decode(const std::vector<std::byte>& bytes) {
  try {
    decode_geometry_file(bytes, "fuzz");
  } catch (const Error&) {
  } catch (const std::bad_alloc&) {
  }
}

}  // namespace

std::vector<std::vector<std::uint8_t>> strielad_fuzz_seeds() {
  HorizontalCoordinates c;
  c.nx = 3;
  c.ny = 2;
  for (std::uint32_t k = 0; k < 6; ++k) {
    c.lon.push_back(10.0 + k % 3 + 0.1 * (k / 3));
    c.lat.push_back(45.0 + 0.5 * (k / 3));
  }
  HorizontalCoordinates surface_only;
  surface_only.nx = 2;
  surface_only.ny = 2;
  surface_only.surface_m = std::vector<double>{0, 12.5, 800, -3};
  HorizontalCoordinates all = c;
  all.surface_m = std::vector<double>{1, 2, 3, 4, 5, 6};
  return {to_u8(encode_geometry_file({7, c})), to_u8(encode_geometry_file({7, surface_only})),
          to_u8(encode_geometry_file({7, all}))};
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::byte> bytes(reinterpret_cast<const std::byte*>(data),
                               reinterpret_cast<const std::byte*>(data) + size);
  decode(bytes);
  if (bytes.size() >= kGeometryHeaderSize) {
    const std::uint64_t header = checksum64(std::span(bytes).first(56));
    std::memcpy(bytes.data() + 56, &header, 8);
    std::uint32_t arrays = 0;
    std::memcpy(&arrays, bytes.data() + 12, 4);
    const std::size_t table = kGeometryArrayEntrySize * std::min<std::uint32_t>(arrays, 3);
    if (bytes.size() >= kGeometryHeaderSize + table + 8) {
      const std::uint64_t sum = checksum64(std::span(bytes).subspan(kGeometryHeaderSize, table));
      std::memcpy(bytes.data() + kGeometryHeaderSize + table, &sum, 8);
    }
    decode(bytes);
  }
  return 0;
}
