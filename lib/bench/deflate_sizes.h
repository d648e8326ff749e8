// SPDX-License-Identifier: Apache-2.0
// NetCDF-4 deflate level 1 size of each variable alone: one `nccopy -k nc4 -d1 -s -c SPEC
// -V VAR` per variable (the file then holds only that variable and the dimensions),
// minus the size of a NetCDF-4 file with the same dimensions and no variables (HDF5
// superblock and dimension scales), so what remains is the variable's chunks and their
// B-tree.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace strielad::bench {

struct DeflateSize {
  std::string variable;
  std::uint64_t file_bytes = 0;  // the nccopy -V output
  std::uint64_t bytes = 0;       // file_bytes - empty_file_bytes
  double seconds = 0;            // nccopy wall time (informative; not fsynced)
};

struct DeflateSizes {
  std::vector<DeflateSize> variables;
  std::uint64_t empty_file_bytes = 0;
  std::string command;  // for one variable, with VAR as placeholder
  const DeflateSize* find(const std::string& name) const;
};

DeflateSizes measure_deflate_sizes(const std::filesystem::path& input,
                                   const std::vector<std::string>& variables,
                                   const std::filesystem::path& work, std::uint32_t brick,
                                   const std::vector<std::string>& nccopy_extra);

}  // namespace strielad::bench
