// SPDX-License-Identifier: Apache-2.0
// Checks every checksum and structural rule of a store (formats/store.md, "What a reader
// must reject") and, for level-0 bricks, that the recorded statistics match the data.
// Reports every problem found instead of stopping at the first.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace strielad {

struct VerifyReport {
  std::uint64_t steps_checked = 0;
  std::uint64_t bricks_checked = 0;
  std::uint64_t chunk_bytes_checked = 0;
  std::vector<std::string> problems;
  bool ok() const { return problems.empty(); }
  nlohmann::json to_json() const;
};

// `progress(done, total)` is called once per checked step.
VerifyReport verify_store(const std::filesystem::path& store,
                          const std::function<void(std::uint64_t, std::uint64_t)>& progress = {});

}  // namespace strielad
