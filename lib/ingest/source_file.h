// SPDX-License-Identifier: Apache-2.0
// Identity of an input file as recorded in the store: absolute path, size and a checksum
// of its first 64 KiB (cheap, and enough to notice a different file under the same name).
#pragma once

#include <filesystem>

#include "ingest/input_catalog.h"

namespace strielad::ingest {

inline constexpr std::size_t kHeaderChecksumBytes = 64 * 1024;

// std::filesystem::absolute(path).lexically_normal() as a string.
std::string absolute_path_string(const std::filesystem::path& path);

// Throws kNotFound (naming the file) when it does not exist, kIo when it cannot be read.
SourceFile describe_source_file(const std::filesystem::path& path);

}  // namespace strielad::ingest
