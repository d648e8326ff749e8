// SPDX-License-Identifier: Apache-2.0
// netCDF-C reads a truncated classic-format file without complaint (samples past the end
// come back as zeros), so truncation is detected here: the header of a CDF-1/2/5 file
// gives every variable's offset and shape, hence the size the file must have.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>

namespace strielad::ingest {

// The number of bytes a classic (CDF-1), 64-bit offset (CDF-2) or 64-bit data (CDF-5)
// file needs for all its variables' data, from the header at the start of `header`.
// nullopt when `header` does not start with a complete classic header (not classic, or
// more bytes are needed) or describes impossible sizes.
std::optional<std::uint64_t> classic_required_size(std::span<const std::byte> header);

// Throws kInvalidInput naming `path` when it starts with a classic-format magic (CDF-1,
// -2 or -5) and its header does not follow the format's grammar (netCDF-C's parser trusts
// the counts it reads and crashes on some), or when the file is shorter than its header
// says ("file is truncated"). Files in other formats pass unchecked.
void check_classic_header(const std::filesystem::path& path);

}  // namespace strielad::ingest
