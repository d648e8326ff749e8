// SPDX-License-Identifier: Apache-2.0
// Files for fuzz targets whose readers take a path: the input written to a file in a
// directory of this process's own (removed at exit), and seeds made by a writer that
// writes a file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace strielad::fuzz {

// A directory of this process's own under $TMPDIR, removed at exit.
const std::filesystem::path& process_dir();

// Writes the bytes to <process_dir()>/input<suffix> (replacing it) and returns its path.
std::filesystem::path input_file(const std::uint8_t* data, std::size_t size,
                                 const std::string& suffix);

// The bytes of a file that `write` writes to the path it is given (a seed).
std::vector<std::uint8_t> bytes_written_by(const std::string& suffix,
                                           const std::function<void(const std::filesystem::path&)>& write);

}  // namespace strielad::fuzz
