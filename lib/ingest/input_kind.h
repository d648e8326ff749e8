// SPDX-License-Identifier: Apache-2.0
// What an input file is, told by its content and never by its name: netCDF classic
// ("CDF" 1, 2 or 5), netCDF-4 (the HDF5 signature at 0, 512, 1024, ... bytes), or GRIB
// ("GRIB" and an edition byte, possibly after a WMO bulletin header).
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>

namespace strielad::ingest {

enum class InputKind { kNetcdfClassic, kNetcdf4, kGrib, kUnknown };

struct InputKindGuess {
  InputKind kind = InputKind::kUnknown;
  int grib_edition = 0;           // kGrib: 1 or 2
  std::uint64_t grib_offset = 0;  // kGrib: where the first message starts
};

// The bytes looked at: a GRIB message may follow a WMO header, and HDF5 allows its
// superblock at 0, 512, 1024, ... (powers of two).
inline constexpr std::size_t kInputKindHeadBytes = 64 * 1024;

// "CDF" and version 1 (classic), 2 (64-bit offset) or 5 (64-bit data).
bool has_classic_magic(std::span<const std::byte> bytes);

// From the first bytes of a file (at most kInputKindHeadBytes are looked at).
InputKindGuess detect_input_kind(std::span<const std::byte> head);
// From the file itself. \error kNotFound, kIo.
InputKindGuess detect_input_kind(const std::filesystem::path& path);

}  // namespace strielad::ingest
