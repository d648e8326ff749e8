// SPDX-License-Identifier: Apache-2.0
#include "support/temp_dir.h"

#include <stdlib.h>

#include <stdexcept>

namespace strielad::testing {

TempDir::TempDir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "strielad-test-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  path_ = pattern;
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

std::filesystem::path ncarg_file(const std::string& relative) {
  return std::filesystem::path(STRIELAD_NCARG_DATA_DIR) / relative;
}

}  // namespace strielad::testing
