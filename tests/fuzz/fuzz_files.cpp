// SPDX-License-Identifier: Apache-2.0
#include "fuzz/fuzz_files.h"

#include <stdlib.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace strielad::fuzz {

const std::filesystem::path& process_dir() {
  // Never destroyed: the exit handler that removes it runs after static destructors.
  static const std::filesystem::path* const dir = [] {
    std::string pattern = (std::filesystem::temp_directory_path() / "strielad-fuzz-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed: " + pattern);
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(process_dir(), ec);
    });
    return new std::filesystem::path(pattern);
  }();
  return *dir;
}

std::filesystem::path input_file(const std::uint8_t* data, std::size_t size,
                                 const std::string& suffix) {
  const auto path = process_dir() / ("input" + suffix);
  FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) throw std::runtime_error("cannot create " + path.string());
  const bool written = size == 0 || std::fwrite(data, 1, size, f) == size;
  if (std::fclose(f) != 0 || !written) throw std::runtime_error("cannot write " + path.string());
  return path;
}

std::vector<std::uint8_t> bytes_written_by(const std::string& suffix,
                                           const std::function<void(const std::filesystem::path&)>& write) {
  const auto path = process_dir() / ("seed" + suffix);
  std::filesystem::remove(path);
  write(path);
  std::ifstream in(path, std::ios::binary);
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(path);
  if (bytes.empty()) throw std::runtime_error("seed writer wrote nothing: " + path.string());
  return bytes;
}

}  // namespace strielad::fuzz
