// SPDX-License-Identifier: Apache-2.0
#include "ingest/input_kind.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <vector>

#include "core/file_io.h"

namespace strielad::ingest {
namespace {

bool starts_with(std::span<const std::byte> bytes, std::size_t at, std::string_view text) {
  return at + text.size() <= bytes.size() &&
         std::memcmp(bytes.data() + at, text.data(), text.size()) == 0;
}

bool is_hdf5(std::span<const std::byte> head) {
  static constexpr std::string_view kSignature{"\x89HDF\r\n\x1a\n", 8};
  if (starts_with(head, 0, kSignature)) return true;
  for (std::size_t at = 512; at < head.size(); at *= 2) {
    if (starts_with(head, at, kSignature)) return true;
  }
  return false;
}

// The first "GRIB" followed (7 bytes on) by edition 1 or 2, as ecCodes finds it.
InputKindGuess find_grib(std::span<const std::byte> head) {
  for (std::size_t at = 0; at + 8 <= head.size(); ++at) {
    if (!starts_with(head, at, "GRIB")) continue;
    const auto edition = std::to_integer<int>(head[at + 7]);
    if (edition == 1 || edition == 2) return {InputKind::kGrib, edition, at};
  }
  return {};
}

}  // namespace

bool has_classic_magic(std::span<const std::byte> bytes) {
  if (bytes.size() < 4) return false;
  const int version = std::to_integer<int>(bytes[3]);
  return bytes[0] == std::byte{'C'} && bytes[1] == std::byte{'D'} && bytes[2] == std::byte{'F'} &&
         (version == 1 || version == 2 || version == 5);
}

InputKindGuess detect_input_kind(std::span<const std::byte> head) {
  head = head.first(std::min(head.size(), kInputKindHeadBytes));
  if (has_classic_magic(head)) return {InputKind::kNetcdfClassic};
  if (is_hdf5(head)) return {InputKind::kNetcdf4};
  return find_grib(head);
}

InputKindGuess detect_input_kind(const std::filesystem::path& path) {
  const ReadOnlyFile file(path);
  std::vector<std::byte> head(
      static_cast<std::size_t>(std::min<std::uint64_t>(file.size(), kInputKindHeadBytes)));
  file.read_at(0, head);
  return detect_input_kind(head);
}

}  // namespace strielad::ingest
