// SPDX-License-Identifier: Apache-2.0
// Fuzzes the content test that tells netCDF classic, netCDF-4 and GRIB inputs apart
// (lib/ingest/input_kind.h): it must never read outside the bytes it is given, and a
// GRIB guess must point at "GRIB" followed by a known edition inside the first 64 KiB.
#include <cstdlib>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "fuzz/fuzz_target.h"
#include "ingest/input_kind.h"

using namespace strielad;

namespace {

std::vector<std::uint8_t> seed(const std::string& bytes) {
  return {bytes.begin(), bytes.end()};
}

}  // namespace

std::vector<std::vector<std::uint8_t>> strielad_fuzz_seeds() {
  return {seed(std::string("CDF\x01\0\0\0\0", 8)),
          seed(std::string("CDF\x05", 4)),
          seed(std::string("\x89HDF\r\n\x1a\n\0\0", 10)),
          seed(std::string("GRIB\0\0\0\x02\0\0\0\0\0\0\0\0", 16)),
          seed(std::string("\x01\r\r\n123\r\r\nYTPB85 KWBC\r\r\nGRIB\0\0\0\x01", 31)),
          seed(std::string(600, '\0') + "\x89HDF\r\n\x1a\n")};
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::byte> head(reinterpret_cast<const std::byte*>(data), size);
  const ingest::InputKindGuess g = ingest::detect_input_kind(head);
  if (g.kind == ingest::InputKind::kGrib) {
    const std::size_t at = g.grib_offset;
    if (at + 8 > size || at + 8 > ingest::kInputKindHeadBytes ||
        std::memcmp(data + at, "GRIB", 4) != 0 || data[at + 7] != g.grib_edition ||
        (g.grib_edition != 1 && g.grib_edition != 2)) {
      std::abort();
    }
  }
  return 0;
}
